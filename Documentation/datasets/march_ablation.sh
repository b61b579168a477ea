#!/bin/bash
# Where a cell step's time goes: the march timed (ppirayBenchmark --breakdown,
# GPU timer queries) with parts of its work taken out, each variant built from
# a worktree of this checkout and timed alternately with the unchanged march.
# The variants render wrong images on purpose; only their times mean
# something (the cost of what they leave out).
#
#   xvfb-run -a -s "-screen 0 1920x1080x24" Documentation/datasets/march_ablation.sh [WORK]
#
# Variants (PARTIAL_PRE_INTEGRATION, tetrahedra):
#   traversal  - no integration: each segment adds a constant (the walk from
#                cell to cell alone: texel fetches, exit-face test)
#   one-piece  - each segment one piece, no split at control points
#                (control interval walk, two transfer-function lookups, Psi)
#   no-psi     - the Psi table lookup replaced by arithmetic
#   no-tf-texels - the transfer function's values and slopes not read (colour
#                and attenuation from arithmetic; the control points, their
#                ends texel and the splits as shipped)
# Environment: ROUNDS (3), WAVELETS ("8 32"), TF (realistic).
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
work="${1:-/tmp/ppiray-ablation}"
rm -rf "$work"
git -C "$here" worktree add -q --detach "$work/src" HEAD
trap 'git -C "$here" worktree remove --force "$work/src"' EXIT
cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DVTK_DIR="${VTK_DIR:-/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk}" > "$work/configure.log"
glsl="$work/src/Rendering/glsl"

variant() { # NAME: builds the tree as it is into $work/NAME/lib
  ninja -C "$work/build" ppirayBenchmark > "$work/build-$1.log"
  mkdir -p "$work/$1/lib"
  cp -a "$work/build/lib/"*.so* "$work/$1/lib/"
}
replace() { # FILE OLD NEW (literal, must occur)
  python3 - "$@" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
assert old in text, (path, old)
open(path, "w").write(text.replace(old, new))
PY
}

variant reference
cp "$glsl/march_fs.glsl" "$work/march_fs.glsl"
replace "$glsl/march_fs.glsl" "    return integrateSegment(sFront, sBack, len, k, color);" \
  "    color += vec4(0.02 * len);
    return k;"
variant traversal
cp "$work/march_fs.glsl" "$glsl/march_fs.glsl"

cp "$glsl/segment_split_fs.glsl" "$work/segment_split_fs.glsl"
python3 - "$glsl/segment_split_fs.glsl" <<'PY'
import sys
path = sys.argv[1]
text = open(path).read()
start = text.index("int integrateSegment")
open(path, "w").write(text[:start] + """int integrateSegment(float sFront, float sBack, float len, int k, inout vec4 color)
{
  k = controlInterval(sFront, k);
  integratePiece(transferFunction(sFront, k), transferFunction(sBack, k), len, color);
  return k;
}
""")
PY
variant one-piece
cp "$work/segment_split_fs.glsl" "$glsl/segment_split_fs.glsl"

cp "$glsl/piece_ppi_fs.glsl" "$work/piece_ppi_fs.glsl"
replace "$glsl/piece_ppi_fs.glsl" "float psi = texture(psiTable, uv).r;" \
  "float psi = 0.5 * (uv.x + uv.y);"
variant no-psi
cp "$work/piece_ppi_fs.glsl" "$glsl/piece_ppi_fs.glsl"

cp "$glsl/transfer_function_fs.glsl" "$work/transfer_function_fs.glsl"
replace "$glsl/transfer_function_fs.glsl" \
  "  return intervalTexel(k, 0) + intervalTexel(k, 1) * (clamp(s, ends.x, ends.y) - ends.x);" \
  "  return vec4(0.5, 0.4, 0.3, 0.01) + 0.001 * float(k) * (clamp(s, ends.x, ends.y) - ends.x);"
replace "$glsl/transfer_function_fs.glsl" "  return ds > 0.0 ? intervalTexel(k, 0) : left;" \
  "  return ds > 0.0 ? vec4(0.5, 0.4, 0.3, 0.01) : left;"
variant no-tf-texels
cp "$work/transfer_function_fs.glsl" "$glsl/transfer_function_fs.glsl"

bench="$work/build/bin/ppirayBenchmark"
for round in $(seq 1 "${ROUNDS:-3}"); do
  for w in ${WAVELETS:-8 32}; do
    for v in reference traversal one-piece no-psi no-tf-texels; do
      ms=$(LD_LIBRARY_PATH="$work/$v/lib" "$bench" --wavelet "$w" --mappers ppiray --views 8 \
        --transfer-function "${TF:-realistic}" --breakdown 2>/dev/null |
        awk -F'|' '$2 ~ /^ march / { gsub(/ /, "", $3); print $3 }')
      echo "round $round wavelet:$w $v: march $ms ms"
    done
  done
done
