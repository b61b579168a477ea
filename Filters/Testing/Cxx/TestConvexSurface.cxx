// ppiray::IsConvexSurface on surfaces whose answer is known by construction:
// convex solids (tetrahedron, icosahedron, subdivided cube, cube with a
// pyramid on a face) and every way of not being one (a dent, a crease, two
// parts, a cavity, an open surface, a flipped triangle, degenerate input), and its
// tolerance (a dent shallower than it counts as flat).

#include "ppirayConvexSurface.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <vector>

namespace
{
struct Surface
{
  std::vector<float> Points;
  std::vector<unsigned int> Triangles;

  unsigned int Add(double x, double y, double z)
  {
    // Vertices at one position are one vertex (faces share their edges).
    const auto key =
      std::make_tuple(std::lround(x * 1e6), std::lround(y * 1e6), std::lround(z * 1e6));
    const auto found = this->Index.find(key);
    if (found != this->Index.end())
    {
      return found->second;
    }
    const unsigned int i = static_cast<unsigned int>(this->Points.size() / 3);
    this->Points.insert(
      this->Points.end(), { static_cast<float>(x), static_cast<float>(y), static_cast<float>(z) });
    this->Index[key] = i;
    return i;
  }
  void Triangle(unsigned int a, unsigned int b, unsigned int c)
  {
    this->Triangles.insert(this->Triangles.end(), { a, b, c });
  }
  std::map<std::tuple<long, long, long>, unsigned int> Index;
};

// The box [lo, hi]^3 (offset by `at`), each face an n x n grid of squares cut
// in two, wound outward (inward with `inward`).
void AddBox(Surface& s, double lo, double hi, int n, double at = 0.0, bool inward = false)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      auto vertex = [&](int i, int j)
      {
        double p[3];
        p[axis] = side ? hi : lo;
        p[(axis + 1) % 3] = lo + (hi - lo) * i / n;
        p[(axis + 2) % 3] = lo + (hi - lo) * j / n;
        return s.Add(p[0] + at, p[1], p[2]);
      };
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          unsigned int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                       d = vertex(i, j + 1);
          // (axis+1, axis+2) is right-handed with the axis: outward on the high side.
          const bool flip = (side == 0) != inward;
          if (flip)
          {
            std::swap(b, d);
          }
          s.Triangle(a, b, c);
          s.Triangle(a, c, d);
        }
      }
    }
  }
}

Surface Tetrahedron()
{
  Surface s;
  const unsigned int a = s.Add(0, 0, 0), b = s.Add(1, 0, 0), c = s.Add(0, 1, 0), d = s.Add(0, 0, 1);
  s.Triangle(a, c, b);
  s.Triangle(a, b, d);
  s.Triangle(a, d, c);
  s.Triangle(b, c, d);
  return s;
}

Surface Icosahedron()
{
  Surface s;
  const double g = 0.5 * (1.0 + std::sqrt(5.0));
  const double v[12][3] = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g },
    { 0, 1, g }, { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 },
    { -g, 0, 1 } };
  for (const auto& p : v)
  {
    s.Add(p[0], p[1], p[2]);
  }
  const unsigned int f[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
    { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 },
    { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
    { 8, 6, 7 }, { 9, 8, 1 } };
  for (const auto& t : f)
  {
    s.Triangle(t[0], t[1], t[2]);
  }
  return s;
}

// The unit cube with its +z face a fan of four triangles to an apex at
// height 1 + dz over the face's centre: a pyramid on it (dz > 0), a dent
// (dz < 0).
Surface CubeWithApex(double dz)
{
  Surface s;
  AddBox(s, 0.0, 1.0, 1);
  // Drop the two triangles of the +z face (all three corners at z = 1).
  std::vector<unsigned int> kept;
  for (size_t t = 0; t < s.Triangles.size(); t += 3)
  {
    bool top = true;
    for (int c = 0; c < 3; ++c)
    {
      top = top && s.Points[3 * s.Triangles[t + c] + 2] == 1.0f;
    }
    if (!top)
    {
      kept.insert(kept.end(), s.Triangles.begin() + t, s.Triangles.begin() + t + 3);
    }
  }
  s.Triangles = kept;
  const unsigned int apex = s.Add(0.5, 0.5, 1.0 + dz);
  const unsigned int corner[4] = { s.Add(0, 0, 1), s.Add(1, 0, 1), s.Add(1, 1, 1), s.Add(0, 1, 1) };
  for (int i = 0; i < 4; ++i)
  {
    s.Triangle(corner[i], corner[(i + 1) % 4], apex);
  }
  return s;
}

// The cube, faces 2 x 2 squares cut in two, with the centre vertex of its +z
// face raised by dz: the cut diagonals not through it make creases.
Surface CubeWithCentreRaised(double dz)
{
  Surface s;
  AddBox(s, 0.0, 1.0, 2);
  const unsigned int centre = s.Add(0.5, 0.5, 1.0);
  s.Points[3 * centre + 2] += static_cast<float>(dz);
  return s;
}
}

int TestConvexSurface(int, char*[])
{
  int errors = 0;
  auto expect = [&](const Surface& s, double tolerance, bool convex, const char* what)
  {
    const bool got = ppiray::IsConvexSurface(s.Points, s.Triangles, tolerance);
    std::printf("%-52s %s (expected %s)\n", what, got ? "convex" : "not convex",
      convex ? "convex" : "not convex");
    errors += got != convex;
  };
  expect(Tetrahedron(), 1e-9, true, "tetrahedron");
  expect(Icosahedron(), 1e-9, true, "icosahedron");
  Surface cube;
  AddBox(cube, 0.0, 1.0, 3);
  expect(cube, 1e-9, true, "cube, faces 3x3 squares (flat edges)");
  expect(CubeWithApex(0.1), 1e-9, true, "cube with a pyramid on a face");
  expect(CubeWithApex(-0.1), 1e-9, false, "cube with a dent");
  expect(CubeWithApex(-1e-4), 1e-3, true, "dent 1e-4, tolerance 1e-3: flat");
  expect(CubeWithApex(-1e-4), 1e-5, false, "dent 1e-4, tolerance 1e-5");
  expect(CubeWithCentreRaised(0.1), 1e-9, false, "grid face, centre raised: creases");

  Surface two;
  AddBox(two, 0.0, 1.0, 1);
  AddBox(two, 0.0, 1.0, 1, 3.0);
  expect(two, 1e-9, false, "two cubes apart");
  Surface cavity;
  AddBox(cavity, 0.0, 3.0, 1);
  AddBox(cavity, 1.0, 2.0, 1, 0.0, true);
  expect(cavity, 1e-9, false, "cube with a cubic cavity");
  Surface open = cube;
  open.Triangles.resize(open.Triangles.size() - 3);
  expect(open, 1e-9, false, "cube less one triangle (open)");
  Surface flipped = cube;
  std::swap(flipped.Triangles[1], flipped.Triangles[2]);
  expect(flipped, 1e-9, false, "cube with one triangle wound inward");
  Surface inside;
  AddBox(inside, 0.0, 1.0, 2, 0.0, true);
  expect(inside, 1e-9, false, "cube wound inward");
  Surface twice = cube;
  twice.Triangles.insert(twice.Triangles.end(), cube.Triangles.begin(), cube.Triangles.begin() + 3);
  expect(twice, 1e-9, false, "cube with a triangle repeated");
  Surface outOfRange = Tetrahedron();
  outOfRange.Triangles[0] = 99;
  expect(outOfRange, 1e-9, false, "an index past the points");
  expect(Surface(), 1e-9, false, "empty");

  std::printf("%d wrong\n", errors);
  return errors == 0 ? 0 : 1;
}
