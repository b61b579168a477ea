"""How TestGPURayCastNonConvexCells' hexahedra were found: distorted
hexahedra (every corner's Jacobian positive, a triangulated surface no line
crosses out of order) and ray directions where the linear cells' exit rule
(cell_linear_fs.glsl: cellExit, cellExitSearch) takes its rare branches.
For parallel rays over each cell it counts the rays whose exit, after some
entry, comes out wrong when the rule is changed:
  noguard  the concave fold's far triangle accepted without the other-face
           guard (tFar <= tNext);
  first    the exit search taking the first face in face order with a
           crossed triangle instead of the nearest;
against the nearest triangle crossed heading out (the definition), and
prints the best shapes for each. A model of the rule for choosing test
cases, in double; the test itself checks the GPU against path lengths and
shares nothing with this script.

Run: /usr/bin/python3 Documentation/datasets/nonconvex_cells_search.py [SEED [SHAPES [SIGMA]]]
(defaults 9 1500 0.3: about a minute; the test's shapes are among its output).
"""
import sys

import numpy as np

FACES = [(0, 4, 7, 3), (1, 2, 6, 5), (0, 1, 5, 4), (3, 7, 6, 2), (0, 3, 2, 1), (4, 5, 6, 7)]
FACE_OF = np.repeat(np.arange(6), 2)


def triangles():
    """Corners of the 12 triangles: each face split along its smallest id's diagonal."""
    out = []
    for q in FACES:
        if q.index(min(q)) % 2 == 0:
            out += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
        else:
            out += [(q[1], q[2], q[3]), (q[1], q[3], q[0])]
    return np.array(out)


TRIANGLES = triangles()


def crossings(points, origins, direction):
    """Per ray and triangle: n . d (> 0 heading out), t, and whether it is crossed."""
    a, b, c = (points[TRIANGLES[:, i]] for i in range(3))
    n = np.cross(b - a, c - a)
    along = np.tile(n @ direction, (len(origins), 1))
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((a[None] - origins[:, None]) * n[None]).sum(-1) / along
    x = origins[:, None] + t[..., None] * direction
    crossed = np.isfinite(t)
    for u, v in ((a, b), (b, c), (c, a)):
        crossed &= (np.cross((v - u)[None], x - u[None]) * n[None]).sum(-1) >= -1e-9 * (n * n).sum(-1)
    return along, t, crossed


def exit_rule(along, t, crossed, t0, entry, guard=True, nearest=True):
    """cellExit, then cellExitSearch where it returns EXIT_SEARCH: face and tExit per entry."""
    rows = np.arange(len(t0))
    candidate = (along > 0) & ((FACE_OF[None] != entry[:, None]) | (t > t0[:, None] + 1e-5 * np.abs(t0[:, None])))
    tc = np.where(candidate, t, np.inf)
    t_face, t_far = np.minimum(tc[:, 0::2], tc[:, 1::2]), np.maximum(tc[:, 0::2], tc[:, 1::2])
    near_side = np.where(tc[:, 0::2] <= tc[:, 1::2], 0, 1)
    plane = np.argmin(t_face, 1)
    t_near, t_far_plane, t_next = t_face[rows, plane], t_far[rows, plane], np.sort(t_face, 1)[:, 1]
    near_ok = crossed[rows, 2 * plane + near_side[rows, plane]]
    far_ok = crossed[rows, 2 * plane + 1 - near_side[rows, plane]]
    ahead = np.isfinite(t_near) & (t_near >= t0 - 1e-6 * np.abs(t0))
    face, t_exit = np.full(len(t0), -1), t0.copy()
    by_near = ahead & near_ok
    by_far = ~by_near & ahead & ((t_far_plane <= t_next) | (not guard)) & far_ok
    face[by_near], t_exit[by_near] = plane[by_near], t_near[by_near]
    face[by_far], t_exit[by_far] = plane[by_far], t_far_plane[by_far]
    search = ~by_near & ~by_far & np.isfinite(t_near)
    hit = np.where(candidate & crossed & (t >= t0[:, None] - 1e-6 * np.abs(t0[:, None])), t, np.inf)
    if nearest:
        j = np.argmin(hit, 1)
        t_hit = hit[rows, j]
    else:
        per_face = np.minimum(hit[:, 0::2], hit[:, 1::2])
        any_face = np.isfinite(per_face)
        first = np.where(any_face.any(1), np.argmax(any_face, 1), 0)
        t_hit, j = per_face[rows, first], 2 * first
    found = search & np.isfinite(t_hit)
    face[found], t_exit[found] = FACE_OF[j[found]], t_hit[found]
    convex = search & ~np.isfinite(t_hit)
    face[convex], t_exit[convex] = plane[convex], t_near[convex]
    return face, np.maximum(t_exit, t0)


def entries(along, t, crossed):
    """Every crossing heading in (ray, t, face); None where a ray's crossings do not alternate."""
    rays, ts, faces = [], [], []
    for r in range(len(t)):
        order = [k for k in np.argsort(t[r]) if crossed[r, k] and along[r, k] != 0]
        sequence = []
        for k in order:
            heading_in = along[r, k] < 0
            if sequence and abs(t[r, k] - sequence[-1][1]) < 1e-9 and sequence[-1][0] == heading_in:
                continue  # the ray through an edge: one crossing of two triangles
            sequence.append((heading_in, t[r, k], FACE_OF[k]))
        if len(sequence) % 2 or any(s[0] != (i % 2 == 0) for i, s in enumerate(sequence)):
            return None
        for heading_in, tk, f in sequence[0::2]:
            rays.append(r)
            ts.append(tk)
            faces.append(f)
    return np.array(rays, int), np.array(ts), np.array(faces, int)


def wrong_rays(points, direction, n=30):
    """Rays over the cell along `direction` whose exit the changed rules get wrong."""
    u = np.cross(direction, [0.3, 0.5, 0.8])
    u /= np.linalg.norm(u)
    v = np.cross(direction, u)
    centre = points.mean(0)
    grid = np.linspace(-1.8, 1.8, n) * np.abs(points - centre).max()
    gu, gv = np.meshgrid(grid, grid)
    origins = centre + gu.reshape(-1, 1) * u + gv.reshape(-1, 1) * v - 4 * direction
    along, t, crossed = crossings(points, origins, direction)
    found = entries(along, t, crossed)
    if found is None or len(found[0]) == 0:
        return None
    rays, t0, entry = found
    hit = np.where(crossed[rays] & (along[rays] > 0) & (t[rays] > t0[:, None] + 1e-7), t[rays], np.inf)
    j = np.argmin(hit, 1)
    truth_face = np.where(np.isfinite(hit[np.arange(len(rays)), j]), FACE_OF[j], -1)
    truth_t = hit[np.arange(len(rays)), j]
    counts = {"rays": len(set(rays))}
    for key, options in (("rule", {}), ("noguard", {"guard": False}), ("first", {"nearest": False})):
        face, t_exit = exit_rule(along[rays], t[rays], crossed[rays], t0, entry, **options)
        wrong = (face != truth_face) | (np.abs(t_exit - truth_t) > 1e-6)
        counts[key] = len(set(rays[wrong]))
    return counts


def valid(points):
    """Every corner's Jacobian (its three edges) positive: a right-handed hexahedron."""
    edges = {0: (1, 3, 4), 1: (2, 0, 5), 2: (3, 1, 6), 3: (0, 2, 7), 4: (7, 5, 0), 5: (4, 6, 1),
             6: (5, 7, 2), 7: (6, 4, 3)}
    return all(np.linalg.det(np.array([points[a] - points[c], points[b] - points[c], points[e] - points[c]])) > 0.02
               for c, (a, b, e) in edges.items())


def main():
    seed, shapes, sigma = (int(sys.argv[1]) if len(sys.argv) > 1 else 9,
                           int(sys.argv[2]) if len(sys.argv) > 2 else 1500,
                           float(sys.argv[3]) if len(sys.argv) > 3 else 0.3)
    cube = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    rng = np.random.default_rng(seed)
    found = []
    for _ in range(shapes):
        points = cube + sigma * rng.normal(size=(8, 3))
        if not valid(points):
            continue
        for _ in range(8):
            direction = rng.normal(size=3)
            direction /= np.linalg.norm(direction)
            counts = wrong_rays(points, direction)
            if counts and counts["rule"] == 0 and (counts["noguard"] or counts["first"]):
                found.append((counts, points.round(3).tolist(), direction.round(3).tolist()))
    for key in ("noguard", "first"):
        found.sort(key=lambda x: -x[0][key] / x[0]["rays"])
        for counts, points, direction in found[:3]:
            print(key, counts, "corners", points, "direction", direction)


if __name__ == "__main__":
    main()
