// Cell textures longer than one buffer texture may be
// (GL_MAX_TEXTURE_BUFFER_SIZE, commonly 2^27 texels: 33.5 M tetrahedra)
// are stored in several and read through one function per array
// (vtkPPIRayBufferTexture::TexelFunction). The split is forced here with
// SetMaximumBufferTexels on small meshes: tetrahedra (geometry in 5 parts,
// neighbours and field in 2) and native hexahedra (geometry in 4). Each
// image must be the unsplit one exactly (the same texels, read from other
// textures) and match the reference; a mesh needing more parts than the
// mapper uses gets one error naming the sizes and draws nothing. Each part
// is a buffer texture as wide as its texels: the count
// GL_MAX_TEXTURE_BUFFER_SIZE bounds and vtkTextureObject checks it against
// (with values instead, a part near the limit logs an error from VTK).

#include "PPIRayImageCompare.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPPIRayBufferTexture.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>
#include <string>

namespace
{
int Compare(const char* what, ppiray_test::Scene& scene, vtkUnstructuredGrid* grid,
  const std::vector<unsigned char>& unsplit)
{
  const auto image = ppiray_test::ReadRGB(scene.Window);
  int largest = 0;
  for (size_t i = 0; i < image.size(); ++i)
  {
    largest = std::max(largest, std::abs(int(image[i]) - int(unsplit[i])));
  }
  std::cout << what << ": max " << largest << "/255 from the unsplit image\n";
  // Same texels, so the same image.
  int errors = 0;
  if (largest != 0)
  {
    std::cout << "FAILED: " << what << " differs from the unsplit image\n";
    ++errors;
  }
  errors += ppiray_test::ExpectReference(
    what, ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, 120, 120), 3000);
  return errors;
}

int Split(const char* what, vtkUnstructuredGrid* grid, int hexahedronMode, vtkIdType texels)
{
  ppiray_test::Scene scene(120, 120);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  mapper->SetHexahedronMode(hexahedronMode);
  vtkNew<ppiray_test::MessageCollector> messages;
  mapper->AddObserver(vtkCommand::ErrorEvent, messages);
  mapper->AddObserver(vtkCommand::WarningEvent, messages);
  scene.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
  scene.Window->Render();
  const auto unsplit = ppiray_test::ReadRGB(scene.Window);
  const vtkIdType bytes = mapper->GetStatistics()->GetGPUMemorySize();
  mapper->SetMaximumBufferTexels(texels);
  scene.Window->Render();
  int errors = Compare(what, scene, grid, unsplit);
  if (mapper->GetStatistics()->GetGPUMemorySize() != bytes || !messages->Errors.empty() ||
      !messages->Warnings.empty())
  {
    std::cout << "FAILED: " << what << ": " << mapper->GetStatistics()->GetGPUMemorySize()
              << " bytes on the GPU, " << bytes << " unsplit; messages [" << messages->Errors
              << messages->Warnings << "]\n";
    ++errors;
  }
  // Back to one buffer per array: the same image again.
  mapper->SetMaximumBufferTexels(0);
  scene.Window->Render();
  errors += Compare("unsplit again", scene, grid, unsplit);
  return errors;
}

// 1,000 texels of 4 floats in parts of at most 300: 4 buffer textures 300,
// 300, 300 and 100 texels wide.
int PartWidths()
{
  ppiray_test::Scene scene(16, 16);
  scene.Window->Render();
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(scene.Window);
  std::vector<float> values(4 * 1000, 1.0f);
  vtkPPIRayBufferTexture buffer;
  const bool uploaded = buffer.Upload(context, values.data(), 1000, 4, VTK_FLOAT, 300);
  std::string widths;
  for (int p = 0; p < buffer.GetNumberOfParts(); ++p)
  {
    widths += std::to_string(buffer.GetTexture(p)->GetWidth()) + " ";
  }
  buffer.ReleaseGraphicsResources(context);
  std::cout << "part widths: " << widths << "\n";
  if (!uploaded || widths != "300 300 300 100 ")
  {
    std::cout << "FAILED: parts are not as wide as their texels (300 300 300 100)\n";
    return 1;
  }
  return 0;
}
}

int TestGPURayCastBufferParts(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int n[3] = { 6, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto all = [](int, int, int) { return true; };
  auto tetrahedra = ppiray_test::VoxelTetrahedra(n, 1.0 / 6, origin, all, ppiray_test::Blob);
  const auto block = ppiray_test::BlobVoxelBlock(6);
  int errors = PartWidths();

  // 1,296 tetrahedra: 5,184 geometry texels (5 parts of 1,200), 1,296
  // neighbour and field texels (2 parts each); in the compact layout 1,296
  // corner, neighbour and value texels (5 parts of 300 each) and 343 points
  // (2 parts).
  const bool compact =
    ppiray_test::TetrahedronLayout() == vtkUnstructuredGridGPURayCastMapper::TETRAHEDRON_COMPACT;
  errors += Split("tetrahedra in parts", tetrahedra,
    vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_SUBDIVIDE, compact ? 300 : 1200);
  // 216 native hexahedra: 1,296 geometry texels in 4 parts of 400.
  errors += Split("hexahedra in parts", block.Hexahedra,
    vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_ACCURATE, 400);

  // More parts than the mapper uses: one error with the sizes, nothing drawn.
  {
    ppiray_test::Scene scene(120, 120);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    mapper->SetMaximumBufferTexels(100);
    scene.Show(mapper, tetrahedra, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    scene.Window->Render();
    const auto image = ppiray_test::ReadRGB(scene.Window);
    int lit = 0;
    for (unsigned char v : image)
    {
      lit += v > 0 ? 1 : 0;
    }
    std::cout << "too many parts: [" << messages->Errors << "], " << lit << " lit values\n";
    const char* expected = compact ? "1296 texels need 13 buffer textures of at most 100"
                                   : "5184 texels need 52 buffer textures of at most 100";
    // The planes layout's error points to the compact one; the compact one's
    // has nothing smaller to offer.
    const bool hint = messages->Errors.find("SetTetrahedronLayoutToCompact") != std::string::npos;
    if (messages->Errors.find(expected) == std::string::npos || hint == compact || lit != 0)
    {
      std::cout << "FAILED: a mesh over the buffer limit is not refused with one clear error\n";
      ++errors;
    }
  }
  return errors ? 1 : 0;
}
