// What a window does to a mapper between frames: a resize (the render
// targets follow the viewport), two viewports with a PPIRay volume each (one
// mapper's targets per renderer, each its own size), and two overlapping
// PPIRay volumes in one renderer (each composited whole over what was
// rendered before it: a documented limit, reported once by a warning; a
// second prop with the same mapper, as ParaView's LOD volume wraps one, is
// not reported); onscreen and offscreen rendering switched between frames,
// and the window closed and reopened (a new OpenGL context); one mapper
// shown in two live windows in turn (each context gets its own GL objects,
// the other's released), and a mapper destroyed while its window lives
// (its GL objects released with it: every texture, buffer, framebuffer,
// renderbuffer, query and vertex array alive in the context counted before
// it rendered and after it was deleted).
//
// Every image against the reference renderer at its viewport's size: every
// covered pixel, p99 and max at most 1/255 (8-bit rounding 0.5, float, the
// 0.1/255 transfer-function tolerance), and the covered pixels counted.

#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include "ppirayVTKCompatibility.h"
#include PPIRAY_VTK_OPENGL_HEADER

#include <array>
#include <iostream>
#include <vector>

namespace
{
// The pixels of the window's image inside [x0, x0 + w) x [y0, y0 + h).
std::vector<unsigned char> Crop(
  const std::vector<unsigned char>& image, int width, int x0, int y0, int w, int h)
{
  std::vector<unsigned char> part;
  for (int y = y0; y < y0 + h; ++y)
  {
    part.insert(
      part.end(), image.begin() + 3 * (y * width + x0), image.begin() + 3 * (y * width + x0 + w));
  }
  return part;
}

// The OpenGL objects alive in the current context among the names
// 1..maxName, by kind: textures, buffers, framebuffers, renderbuffers, queries,
// vertex arrays (a generated name is an object once bound or begun).
std::array<int, 6> CountGLObjects(GLuint maxName)
{
  std::array<int, 6> count{};
  for (GLuint name = 1; name <= maxName; ++name)
  {
    count[0] += glIsTexture(name) ? 1 : 0;
    count[1] += glIsBuffer(name) ? 1 : 0;
    count[2] += glIsFramebuffer(name) ? 1 : 0;
    count[3] += glIsRenderbuffer(name) ? 1 : 0;
    count[4] += glIsQuery(name) ? 1 : 0;
    count[5] += glIsVertexArray(name) ? 1 : 0;
  }
  return count;
}

void PrintGLObjects(const char* what, const std::array<int, 6>& count)
{
  std::cout << what << ": " << count[0] << " textures, " << count[1] << " buffers, " << count[2]
            << " framebuffers, " << count[3] << " renderbuffers, " << count[4] << " queries, "
            << count[5] << " vertex arrays\n";
}

}

int TestGPURayCastWindows(int, char*[])
{
  const int n[3] = { 6, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto all = [](int, int, int) { return true; };
  auto grid = ppiray_test::VoxelTetrahedra(n, 1.0 / 6, origin, all, ppiray_test::Blob);
  int errors = 0;

  // 1. A resize between renders.
  {
    ppiray_test::Scene scene(120, 120);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    scene.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    scene.Window->Render();
    errors += ppiray_test::ExpectReference("120x120",
      ppiray_test::CheckPixels(
        scene.Renderer, grid, scene.Property, ppiray_test::ReadRGB(scene.Window), 120, 120),
      2000);
    scene.Window->SetSize(170, 130);
    scene.Window->Render();
    errors += ppiray_test::ExpectReference("resized to 170x130",
      ppiray_test::CheckPixels(
        scene.Renderer, grid, scene.Property, ppiray_test::ReadRGB(scene.Window), 170, 130),
      2000);
  }

  // 2. Two viewports, a PPIRay volume in each, seen from two sides.
  {
    ppiray_test::Scene scene(240, 120);
    scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> left;
    scene.Show(left, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    vtkNew<vtkRenderer> second;
    second->SetViewport(0.5, 0.0, 1.0, 1.0);
    second->SetBackground(0.0, 0.0, 0.0);
    scene.Window->AddRenderer(second);
    vtkNew<vtkVolume> volume;
    volume->SetProperty(scene.Property);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> right;
    right->SetInputData(grid);
    volume->SetMapper(right);
    second->AddVolume(volume);
    second->GetActiveCamera()->SetPosition(-1.5, 2.5, -0.8);
    second->GetActiveCamera()->SetFocalPoint(0.5, 0.5, 0.5);
    second->ResetCamera();
    scene.Window->Render();
    const auto image = ppiray_test::ReadRGB(scene.Window);
    errors += ppiray_test::ExpectReference("left viewport",
      ppiray_test::CheckPixels(
        scene.Renderer, grid, scene.Property, Crop(image, 240, 0, 0, 120, 120), 120, 120),
      2000);
    errors += ppiray_test::ExpectReference("right viewport",
      ppiray_test::CheckPixels(
        second, grid, scene.Property, Crop(image, 240, 120, 0, 120, 120), 120, 120),
      2000);
  }

  // 3. Two overlapping PPIRay volumes in one renderer: a warning, once.
  {
    ppiray_test::Scene scene(120, 120);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> first;
    vtkNew<ppiray_test::MessageCollector> messages;
    first->AddObserver(vtkCommand::WarningEvent, messages);
    scene.Show(first, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    vtkNew<vtkVolume> volume;
    volume->SetProperty(scene.Property);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> other;
    other->SetInputData(grid);
    volume->SetMapper(other);
    volume->SetPosition(0.3, 0.2, 0.1);
    scene.Renderer->AddVolume(volume);
    scene.Window->Render();
    scene.Window->Render();
    const size_t first_at = messages->Warnings.find("overlap");
    std::cout << "overlapping volumes: [" << messages->Warnings << "]\n";
    if (first_at == std::string::npos ||
        messages->Warnings.find("overlap", first_at + 1) != std::string::npos)
    {
      std::cout << "FAILED: overlapping PPIRay volumes are not reported once\n";
      ++errors;
    }
  }
  // 4. A prop wrapping a volume with the same mapper (as ParaView's
  // vtkPVLODVolume does) is not another volume: no warning.
  {
    ppiray_test::Scene scene(120, 120);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    scene.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    vtkNew<vtkVolume> wrapper;
    wrapper->SetMapper(mapper);
    wrapper->SetProperty(scene.Property);
    scene.Renderer->AddVolume(wrapper);
    scene.Window->Render();
    std::cout << "a volume sharing the mapper: [" << messages->Warnings << "]\n";
    if (messages->Warnings.find("overlap") != std::string::npos)
    {
      std::cout << "FAILED: a volume sharing this mapper is reported as overlapping\n";
      ++errors;
    }
  }
  // 5. Onscreen, offscreen, onscreen again, then the window closed and
  // reopened (its context and every GL object released, a new context
  // made): each frame as the reference, no stale target or program.
  {
    ppiray_test::Scene scene(120, 110);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    scene.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    auto check = [&](const char* what)
    {
      scene.Window->Render();
      errors += ppiray_test::ExpectReference(what,
        ppiray_test::CheckPixels(
          scene.Renderer, grid, scene.Property, ppiray_test::ReadRGB(scene.Window), 120, 110),
        2000);
    };
    check("onscreen");
    scene.Window->SetOffScreenRendering(1);
    check("offscreen");
    scene.Window->SetOffScreenRendering(0);
    check("onscreen again");
    scene.Window->Finalize();
    check("closed and reopened");
    if (!messages->Warnings.empty() || !messages->Errors.empty())
    {
      std::cout << "FAILED: messages switching windows: [" << messages->Warnings << messages->Errors
                << "]\n";
      ++errors;
    }
  }
  // 6. One mapper in two live windows (two volumes sharing it), rendered in
  // turn: GL objects belong to one context, so each switch releases them in
  // the other and makes them again.
  {
    ppiray_test::Scene a(120, 110), b(100, 120);
    ppiray_test::SmoothTransferFunction(a.Property, 0.0, 1.3, 0.8, 0.2);
    ppiray_test::SmoothTransferFunction(b.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    a.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    b.Show(mapper, grid, { -1.5, 2.5, -0.8 }, { 0.5, 0.5, 0.5 });
    for (int round = 0; round < 2; ++round)
    {
      for (auto* scene : { &a, &b })
      {
        scene->Window->Render();
        const int* size = scene->Window->GetSize();
        errors +=
          ppiray_test::ExpectReference(scene == &a ? "two windows, first" : "two windows, second",
            ppiray_test::CheckPixels(scene->Renderer, grid, scene->Property,
              ppiray_test::ReadRGB(scene->Window), size[0], size[1]),
            2000);
      }
    }
    if (!messages->Warnings.empty() || !messages->Errors.empty())
    {
      std::cout << "FAILED: messages in two windows: [" << messages->Warnings << messages->Errors
                << "]\n";
      ++errors;
    }
  }
  // 7. A mapper destroyed while its window lives, without
  // ReleaseGraphicsResources: another mapper renders right after it.
  {
    ppiray_test::Scene scene(120, 110);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    {
      vtkNew<vtkUnstructuredGridGPURayCastMapper> doomed;
      scene.Show(doomed, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
      scene.Window->Render();
      scene.Volume->SetMapper(nullptr);
    }
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    scene.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    scene.Window->Render();
    errors += ppiray_test::ExpectReference("after a mapper was destroyed",
      ppiray_test::CheckPixels(
        scene.Renderer, grid, scene.Property, ppiray_test::ReadRGB(scene.Window), 120, 110),
      2000);
  }
  // 8. The GL objects of a mapper destroyed without ReleaseGraphicsResources
  // are all gone: counted in the context before it rendered and after it was
  // deleted (shader programs stay in the window's shader cache, as for VTK's
  // mappers).
  {
    ppiray_test::Scene scene(120, 110);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    scene.Renderer->RemoveVolume(scene.Volume);
    scene.Window->Render();
    const GLuint maxName = 4096;
    scene.Window->MakeCurrent();
    // The window's shared full-screen quad buffer (vtkOpenGLQuadHelper's,
    // owned by the window, made on first use: a window that blits its frame
    // has it already, an OSMesa window not) is the window's, not the mapper's.
    vtkOpenGLRenderWindow::SafeDownCast(scene.Window)->GetTQuad2DVBO();
    const auto before = CountGLObjects(maxName);
    std::array<int, 6> during{};
    {
      vtkNew<vtkUnstructuredGridGPURayCastMapper> doomed;
      scene.Renderer->AddVolume(scene.Volume);
      scene.Show(doomed, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
      scene.Window->Render();
      errors += ppiray_test::ExpectReference("counted mapper",
        ppiray_test::CheckPixels(
          scene.Renderer, grid, scene.Property, ppiray_test::ReadRGB(scene.Window), 120, 110),
        2000);
      scene.Window->MakeCurrent();
      during = CountGLObjects(maxName);
      scene.Renderer->RemoveVolume(scene.Volume);
      scene.Volume->SetMapper(nullptr);
    }
    scene.Window->MakeCurrent();
    const auto after = CountGLObjects(maxName);
    PrintGLObjects("GL objects before the mapper", before);
    PrintGLObjects("GL objects while it renders", during);
    PrintGLObjects("GL objects after its destructor", after);
    // The count must see the mapper's objects (at least its textures,
    // framebuffer and query) for its return to mean anything.
    if (during[0] <= before[0] || during[2] <= before[2] || during[4] <= before[4])
    {
      std::cout << "FAILED: the mapper's GL objects were not counted\n";
      ++errors;
    }
    if (after != before)
    {
      std::cout << "FAILED: GL objects left after the mapper's destructor\n";
      ++errors;
    }
  }
  return errors ? 1 : 0;
}
