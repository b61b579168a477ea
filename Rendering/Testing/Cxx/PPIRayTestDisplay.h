// The test process's X display (see PPIRayTestDisplay.cxx), or nullptr where
// there is no X11 (VTK then opens its own).
#ifndef PPIRayTestDisplay_h
#define PPIRayTestDisplay_h

namespace ppiray_test
{
void* SharedDisplay();
}

#endif
