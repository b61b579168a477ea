// One X display connection per test process, opened with retries.
//
// Under Xvfb, XOpenDisplay fails now and then (measured here: 70-170 of 2000
// back-to-back connections, xcb error XCB_CONN_ERROR during the connection
// setup, with an idle server and raw connect() never failing). VTK opens a new
// connection for every render window and aborts when that fails, so a test
// that creates several windows would fail at random. The tests hand VTK this
// one connection instead (vtkRenderWindow::SetDisplayId).
#include "PPIRayTestDisplay.h"

#if PPIRAY_TEST_HAS_X11
#include <X11/Xlib.h>
#include <chrono>
#include <thread>
#endif

namespace ppiray_test
{
void* SharedDisplay()
{
#if PPIRAY_TEST_HAS_X11
  static Display* display = []() -> Display*
  {
    for (int attempt = 0; attempt < 50; ++attempt)
    {
      if (Display* d = XOpenDisplay(nullptr))
      {
        return d;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return nullptr;
  }();
  return display;
#else
  return nullptr;
#endif
}
}
