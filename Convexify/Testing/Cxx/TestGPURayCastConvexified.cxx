// Non-convex meshes rendered as they are (depth peeling: one pass per
// re-entry) and convexified (vtkUnstructuredGridConvexify: imaginary cells,
// hidden, traversed without emission): the convexified grid renders in one
// peel, and its image equals the peeled one and the CPU reference of the
// original mesh (every covered pixel, p99 and max at most 1/255: 8-bit
// rounding 0.5, float, the 0.1/255 transfer-function tolerance). The
// reference of the convexified grid (hidden cells left out) is checked too.
// Scenes: a block with a tunnel beside a second block (the non-convex test's
// mesh), a cube with a cavity, two parts across a thin gap, the benchmark's
// carved wavelet (graded holes), three cavities in a row (a lattice: 4 peels,
// a fill with Steiner points), an image clipped and tetrahedralized as
// ParaView's filters do it (zero-volume cells, faces of three cells, points
// a few roundings apart, two parts; PPIRayClippedImage.h).
// NON_CONVEX_AUTOMATIC on each scene, three frames: the first peels; where
// it took at least 4 peels the second is convexified (the trial), and the
// third too where the fill is small (imaginary cells at most the cells,
// Steiner points at most 1e-3 of the points), else it peels; each frame's
// image is the peeled or the convexified one to the bit, as chosen
// (GetNonConvexChoice()); a fourth frame, of a new grid with the same
// arrays (a time series' step), keeps the third's choice. A lattice of hexahedra with holes,
// marched natively with many peels, is peeled without trying the fill.

#include "PPIRayClippedImage.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkObjectFactory.h"
#include "vtkObjectFactoryCollection.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGridConvexify.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// `direction`: from the mesh's centre towards the eye (any length).
int Compare(const char* name, vtkUnstructuredGrid* grid, const std::array<double, 3>& direction,
  double lo, double hi)
{
  const int size = 160;
  vtkNew<vtkUnstructuredGridConvexify> convexify;
  convexify->SetInputData(grid);
  convexify->Update();
  vtkUnstructuredGrid* convex = convexify->GetOutput();

  ppiray_test::Scene scene(size, size);
  ppiray_test::SmoothTransferFunction(scene.Property, lo, hi, 0.7, 0.1);
  double b[6];
  grid->GetBounds(b);
  const std::array<double, 3> centre{ 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]),
    0.5 * (b[4] + b[5]) };
  const double reach = 2.0 *
                       std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                 (b[5] - b[4]) * (b[5] - b[4])) /
                       std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                 direction[2] * direction[2]);
  const std::array<double, 3> eye{ centre[0] + reach * direction[0],
    centre[1] + reach * direction[1], centre[2] + reach * direction[2] };
  vtkNew<vtkUnstructuredGridGPURayCastMapper> peeled;
  scene.Show(peeled, grid, eye, centre);
  scene.Window->Render();
  const auto peeledImage = ppiray_test::ReadRGB(scene.Window);
  const int peels = peeled->GetStatistics()->GetNumberOfPeels();

  vtkNew<vtkUnstructuredGridGPURayCastMapper> oneLayer;
  ppiray_test::UseTetrahedronLayout(oneLayer);
  vtkNew<ppiray_test::MessageCollector> messages;
  oneLayer->AddObserver(vtkCommand::WarningEvent, messages);
  oneLayer->AddObserver(vtkCommand::ErrorEvent, messages);
  scene.Volume->SetMapper(oneLayer);
  oneLayer->SetInputData(convex);
  scene.Window->Render();
  const auto convexImage = ppiray_test::ReadRGB(scene.Window);
  const int convexPeels = oneLayer->GetStatistics()->GetNumberOfPeels();

  int largest = 0;
  for (size_t i = 0; i < convexImage.size(); ++i)
  {
    largest = std::max(largest, std::abs(int(convexImage[i]) - int(peeledImage[i])));
  }
  // The same through the mapper: NON_CONVEX_CONVEXIFY with the filter
  // plugged in (run by the mapper, kept until the input changes).
  vtkNew<vtkUnstructuredGridGPURayCastMapper> byMode;
  ppiray_test::UseTetrahedronLayout(byMode);
  vtkNew<vtkUnstructuredGridConvexify> plugged;
  byMode->SetNonConvexModeToConvexify();
  byMode->SetConvexifier(plugged);
  byMode->AddObserver(vtkCommand::WarningEvent, messages);
  byMode->AddObserver(vtkCommand::ErrorEvent, messages);
  scene.Volume->SetMapper(byMode);
  byMode->SetInputData(grid);
  scene.Window->Render();
  scene.Window->Render();
  const auto modeImage = ppiray_test::ReadRGB(scene.Window);
  const bool modeSame =
    modeImage == convexImage && byMode->GetStatistics()->GetNumberOfPeels() == convexPeels &&
    plugged->GetNumberOfImaginaryCells() == convexify->GetNumberOfImaginaryCells();
  // NON_CONVEX_AUTOMATIC: the choice expected from the rule, frame by frame.
  const bool smallFill = convexify->GetNumberOfImaginaryCells() <= grid->GetNumberOfCells() &&
                         convexify->GetNumberOfSteinerPoints() <= 1e-3 * grid->GetNumberOfPoints();
  const bool convexifies = peels >= 4 && smallFill && convexPeels <= 2;
  vtkNew<vtkUnstructuredGridGPURayCastMapper> automatic;
  ppiray_test::UseTetrahedronLayout(automatic);
  vtkNew<vtkUnstructuredGridConvexify> automaticFill;
  automatic->SetNonConvexModeToAutomatic();
  automatic->SetConvexifier(automaticFill);
  scene.Volume->SetMapper(automatic);
  automatic->SetInputData(grid);
  std::string choices;
  bool automaticSame = true;
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Window->Render();
    const bool convexified = automatic->GetNonConvexChoice() == automatic->NON_CONVEX_CONVEXIFY;
    choices += convexified ? "C" : "P";
    // The second frame tries the fill wherever the first took 4 peels.
    const bool expected = (frame == 1 && peels >= 4) || (frame == 2 && convexifies);
    automaticSame = automaticSame && convexified == expected &&
                    ppiray_test::ReadRGB(scene.Window) == (convexified ? convexImage : peeledImage);
  }
  // A time series' next step (a new grid, the same arrays) keeps the choice.
  auto next = vtkSmartPointer<vtkUnstructuredGrid>::New();
  next->ShallowCopy(grid);
  automatic->SetInputData(next);
  scene.Window->Render();
  const bool kept = automatic->GetNonConvexChoice() == automatic->NON_CONVEX_CONVEXIFY;
  choices += kept ? "C" : "P";
  automaticSame = automaticSame && kept == convexifies;
  std::cout << name << ": " << grid->GetNumberOfCells() << " cells + "
            << convexify->GetNumberOfImaginaryCells() << " imaginary, "
            << convexify->GetNumberOfSteinerPoints() << " Steiner points; " << peels
            << " peels as it is, " << convexPeels << " convexified; max " << largest
            << "/255 between the two images; boundary faces joined to imaginary ones "
            << oneLayer->GetStatistics()->GetNumberOfLinkedBoundaryFaces() << " ("
            << oneLayer->GetStatistics()->GetNumberOfSplitBoundaryFaces() << " split), left open "
            << oneLayer->GetStatistics()->GetNumberOfUnlinkedBoundaryFaces()
            << "; automatic, four frames: " << choices << "\n";
  // Without Steiner points every face is shared by point ids; with them the
  // split faces are crossed into their pieces (and a face met through other
  // point ids is joined too): one peel either way, every face joined.
  const bool split = convexify->GetNumberOfSteinerPoints() > 0;
  int errors = 0;
  if (split != (oneLayer->GetStatistics()->GetNumberOfSplitBoundaryFaces() > 0) ||
      oneLayer->GetStatistics()->GetNumberOfUnlinkedBoundaryFaces() != 0)
  {
    std::cout << "FAILED: " << name << ": expected split faces exactly with Steiner points, and "
              << "none left open\n";
    ++errors;
  }
  if (!automaticSame)
  {
    std::cout << "FAILED: " << name << ": NON_CONVEX_AUTOMATIC chose " << choices << ", expected "
              << (convexifies ? "PCCC" : (peels >= 4 ? "PCPP" : "PPPP"))
              << " with the chosen images\n";
    ++errors;
  }
  if (!modeSame)
  {
    std::cout << "FAILED: " << name << ": NON_CONVEX_CONVEXIFY differs from the convexified "
              << "grid rendered as input (" << byMode->GetStatistics()->GetNumberOfPeels()
              << " peels)\n";
    ++errors;
  }
  if (peels < 2 || convexPeels != 1 || largest > 1 || !messages->Errors.empty() ||
      (!split && !messages->Warnings.empty()))
  {
    std::cout << "FAILED: " << name << ": expected several peels as it is, one convexified, "
              << "images within 1/255 and no messages [" << messages->Warnings << messages->Errors
              << "]\n";
    ++errors;
  }
  errors += ppiray_test::ExpectReference((std::string(name) + ", convexified, against the "
                                                              "original's reference")
                                           .c_str(),
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, convexImage, size, size),
    size * size / 8);
  errors += ppiray_test::ExpectReference((std::string(name) + ", convexified, against its own "
                                                              "reference")
                                           .c_str(),
    ppiray_test::CheckPixels(scene.Renderer, convex, scene.Property, convexImage, size, size),
    size * size / 8);
  return errors;
}
}

int TestGPURayCastConvexified(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  int errors = 0;
  {
    auto grid = ppiray_test::TunnelAndBlock();
    errors += Compare("tunnel and a second block", grid, { -0.9, 0.75, 0.9 }, 0.0, 1.3);
  }
  {
    const int n[3] = { 6, 6, 6 };
    const double origin[3] = { 0, 0, 0 };
    auto keep = [](int i, int j, int k)
    { return !(i >= 2 && i < 4 && j >= 2 && j < 4 && k >= 2 && k < 4); };
    auto grid = ppiray_test::VoxelTetrahedra(
      n, 1.0 / 6, origin, keep, [](double x, double y, double z) { return x + y + z; });
    errors += Compare("cube with a cavity", grid, { 2.2, 1.6, 2.5 }, 0.0, 3.0);
  }
  {
    // Two parts across a thin gap (1e-3 of their size): a 7x3x3 lattice
    // without its middle slab of voxels, the far part moved back to 1e-3
    // from the near one.
    const int n[3] = { 7, 3, 3 };
    const double origin[3] = { 0, 0, 0 };
    auto grid = ppiray_test::VoxelTetrahedra(
      n, 1.0 / 3, origin, [](int i, int, int) { return i != 3; },
      [](double x, double y, double z) { return x + y + z; });
    vtkPoints* points = grid->GetPoints();
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
      double x[3];
      points->GetPoint(p, x);
      x[0] -= x[0] > 1.1 ? 1.0 / 3 - 1e-3 : 0.0;
      points->SetPoint(p, x);
    }
    errors += Compare("two parts across a thin gap", grid, { 1.0, 0.35, 0.25 }, 0.0, 4.0);
  }
  {
    // Three cavities in a row along x, seen along x: 4 peels.
    const int n[3] = { 7, 3, 3 };
    const double origin[3] = { 0, 0, 0 };
    auto grid = ppiray_test::VoxelTetrahedra(
      n, 1.0 / 3, origin, [](int i, int j, int k) { return !(i % 2 == 1 && j == 1 && k == 1); },
      [](double x, double y, double z) { return x + y + z; });
    errors += Compare("three cavities in a row", grid, { 1.0, 0.05, 0.03 }, 0.0, 4.0);
  }
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((std::string(PPIRAY_SOURCE_DIR) + "/Data/graded_holes.vtu").c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    errors += Compare("graded_holes.vtu", grid, { 1.0, 0.6, 1.4 }, range[0], range[1]);
  }
  {
    auto grid = ppiray_test::ClippedImage(6);
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    errors +=
      Compare("image clipped and tetrahedralized", grid, { 0.3, 1.0, 0.4 }, range[0], range[1]);
  }
  {
    // Hexahedra marched natively, three cavities in a row (4 peels): peeled,
    // the fill never tried.
    const int n[3] = { 7, 3, 3 };
    const double origin[3] = { 0, 0, 0 };
    auto grid = ppiray_test::VoxelTetrahedra(
      n, 1.0 / 3, origin, [](int i, int j, int k) { return !(i % 2 == 1 && j == 1 && k == 1); },
      [](double x, double y, double z) { return x + y + z; }, /*hexahedra=*/true);
    ppiray_test::Scene scene(120, 120);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 4.0, 0.7, 0.1);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> automatic;
    vtkNew<vtkUnstructuredGridConvexify> fill;
    automatic->SetNonConvexModeToAutomatic();
    automatic->SetConvexifier(fill);
    scene.Show(automatic, grid, { 4.0, 0.55, 0.53 }, { 1.17, 0.5, 0.5 });
    int peels = 0;
    for (int frame = 0; frame < 3; ++frame)
    {
      scene.Window->Render();
      peels = std::max(peels, automatic->GetStatistics()->GetNumberOfPeels());
      errors += automatic->GetNonConvexChoice() == automatic->NON_CONVEX_PEEL ? 0 : 1;
    }
    std::cout << "hexahedra, three cavities in a row: " << peels << " peels, "
              << automatic->GetStatistics()->GetNumberOfNativeCells() << " native cells, fill "
              << fill->GetOutput()->GetNumberOfCells() << " cells\n";
    if (peels < 4 || automatic->GetStatistics()->GetNumberOfNativeCells() == 0 ||
        fill->GetOutput()->GetNumberOfCells() != 0)
    {
      std::cout << "FAILED: native hexahedra: expected peeled without trying the fill\n";
      ++errors;
    }
  }
  // NON_CONVEX_CONVEXIFY without a Convexifier: one made by VTK's object
  // factory (this module registers vtkUnstructuredGridConvexify when it is
  // loaded): the same peels and image as with the filter set explicitly, no
  // "No Convexifier" warning. With that factory unregistered: that warning,
  // then peeling.
  vtkObjectFactory* factory = nullptr;
  {
    vtkCollectionSimpleIterator it;
    auto* factories = vtkObjectFactory::GetRegisteredFactories();
    factories->InitTraversal(it);
    while (auto* f = factories->GetNextObjectFactory(it))
    {
      factory = std::string(f->GetDescription()) == "PPIRay::Convexify" ? f : factory;
    }
  }
  if (!factory)
  {
    std::cout << "FAILED: PPIRay::Convexify registered no object factory\n";
    return 1;
  }
  vtkSmartPointer<vtkObjectFactory> keep = factory; // while unregistered
  // Peels and image of the tunnel scene in NON_CONVEX_CONVEXIFY.
  auto render = [](vtkUnstructuredGridAlgorithm* convexifier,
                  ppiray_test::MessageCollector* messages, bool& made,
                  std::vector<unsigned char>& image)
  {
    ppiray_test::Scene scene(64, 64);
    auto grid = ppiray_test::TunnelAndBlock();
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.7, 0.1);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->SetNonConvexModeToConvexify();
    mapper->SetConvexifier(convexifier);
    scene.Show(mapper, grid, { -0.9, 0.75, 0.9 }, { 0.5, 0.3, 0.3 });
    scene.Window->Render();
    scene.Window->Render();
    made = vtkUnstructuredGridConvexify::SafeDownCast(mapper->GetConvexifier()) != nullptr;
    image = ppiray_test::ReadRGB(scene.Window);
    return mapper->GetStatistics()->GetNumberOfPeels();
  };
  vtkNew<ppiray_test::MessageCollector> explicitMessages;
  vtkNew<vtkUnstructuredGridConvexify> explicitConvexify;
  bool made = false;
  std::vector<unsigned char> explicitImage, image;
  const int explicitPeels = render(explicitConvexify, explicitMessages, made, explicitImage);
  for (const bool registered : { true, false })
  {
    if (!registered)
    {
      vtkObjectFactory::UnRegisterFactory(factory);
    }
    vtkNew<ppiray_test::MessageCollector> messages;
    const int peels = render(nullptr, messages, made, image);
    const bool warned = messages->Warnings.find("No Convexifier") != std::string::npos;
    std::cout << "no Convexifier set, factory " << (registered ? "registered" : "unregistered")
              << ": " << peels << " peels (" << explicitPeels
              << " with the filter set), convexifier " << (made ? "made" : "none") << ", image "
              << (image == explicitImage ? "equal" : "different") << (warned ? ", warned" : "")
              << "\n";
    if (registered ? (!made || peels != explicitPeels || image != explicitImage || warned)
                   : (made || !warned || peels == explicitPeels))
    {
      std::cout << "FAILED: NON_CONVEX_CONVEXIFY without a Convexifier set, factory "
                << (registered ? "registered: not as with the filter set"
                               : "unregistered: did not warn and peel")
                << "\n";
      ++errors;
    }
  }
  // Left unregistered: vtkObjectFactory::RegisterFactory allocates a
  // factory's library strings on every call, so registering this one again
  // would leak the first ones; the module unregisters it at exit either way.
  return errors ? 1 : 0;
}
