#!/bin/bash
# Instructions the JIT-compiled shaders of llvmpipe execute for one frame of
# each of two builds of PPIRay (callgrind's count for the largest block of
# code without a symbol: the march shader), one thread: deterministic, where
# frame times on a shared 2-core machine vary by 20 % from run to run.
#
#   git worktree add /tmp/ppiray-a <commit> && (cd /tmp/ppiray-a && Module/run build)
#   Module/run python Documentation/datasets/write_vtu.py /tmp/meshes bluntfin lox_post
#   xvfb-run -a -s "-screen 0 1280x1024x24" \
#     Documentation/datasets/ab_instructions.sh /tmp/ppiray-a/build build \
#     /tmp/meshes/bluntfin_given.vtu /tmp/meshes/lox_post_given.vtu wavelet:8
#
# A mesh is a .vtu file, or wavelet:N (ppirayBenchmark's generated wavelet).
# Options by environment: SIZE (128x128), MAPPER (ppiray-exact: no Psi table
# to build under valgrind, the same march for native cells), MAPPER_B (B's
# mapper, default MAPPER: one build's two mappers compared, e.g. MAPPER=
# ppiray-subdivide MAPPER_B=ppiray with A = B), STAGE (the march stage,
# fragment or compute; default the mapper's), JIT=all (the instructions of
# every JIT-compiled block summed: the march and the passes around it, e.g.
# the compute stage's ray queue).
set -euo pipefail
a=$1
b=$2
shift 2
count() {
  local build=$1 mapper=$2 out
  out=$(mktemp)
  local stage=()
  [ -n "${STAGE:-}" ] && stage=(--march-stage "$STAGE")
  LP_NUM_THREADS=1 LD_LIBRARY_PATH="$build/lib" valgrind --tool=callgrind --smc-check=all \
    --callgrind-out-file="$out" "$build/bin/ppirayBenchmark" "${source[@]}" \
    --size "${SIZE:-128x128}" --views 1 --mappers "$mapper" "${stage[@]}" \
    --transfer-function realistic >/dev/null 2>&1
  callgrind_annotate "$out" 2>/dev/null | grep '???:0x' | grep -v '\.so' |
    head -"$([ "${JIT:-}" = all ] && echo 1000000 || echo 1)" |
    awk '{gsub(/,/, "", $1); n += $1} END { printf "%.0f\n", n }'
  rm -f "$out"
}
for mesh in "$@"; do
  if [[ "$mesh" == wavelet:* ]]; then
    source=(--wavelet "${mesh#wavelet:}")
  else
    source=(--file "$mesh")
  fi
  ia=$(count "$a" "${MAPPER:-ppiray-exact}")
  ib=$(count "$b" "${MAPPER_B:-${MAPPER:-ppiray-exact}}")
  echo "$(basename "$mesh"): A $ia, B $ib instructions, B/A" \
    "$(awk -v x="$ib" -v y="$ia" 'BEGIN { printf "%.3f", x / y }')"
done
