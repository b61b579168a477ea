#!/bin/bash
# Frame times of two builds of PPIRay on the same meshes, alternating A and B
# within each round so that both see the same machine state (peers in the
# same run); prints each pair and the ratio B/A.
#
#   git worktree add /tmp/ppiray-a <commit> && (cd /tmp/ppiray-a && Module/run build)
#   Module/run python Documentation/datasets/write_vtu.py /tmp/meshes
#   xvfb-run -a -s "-screen 0 1920x1080x24" \
#     Documentation/datasets/ab_frames.sh /tmp/ppiray-a/build build /tmp/meshes/*.vtu wavelet:32
#
# A mesh is a .vtu file, or wavelet:N (ppirayBenchmark's generated wavelet of
# half extent N). Options by environment: ROUNDS (default 4), SIZE (512x512),
# VIEWS (8), MAPPERS (ppiray; a comma-separated list of ppirayBenchmark's
# mapper names, each timed on its own), BENCH_ARGS (more ppirayBenchmark options,
# e.g. "--transfer-function realistic"; both builds must know them).
set -euo pipefail
a=$1
b=$2
shift 2
IFS=, read -r -a mappers <<< "${MAPPERS:-ppiray}"
for round in $(seq 1 "${ROUNDS:-4}"); do
  for mesh in "$@"; do
    if [[ "$mesh" == wavelet:* ]]; then
      source=(--wavelet "${mesh#wavelet:}")
    else
      source=(--file "$mesh")
    fi
    for mapper in "${mappers[@]}"; do
      declare -A ms
      for build in "$a" "$b"; do
        line=$(LD_LIBRARY_PATH="$build/lib" "$build/bin/ppirayBenchmark" "${source[@]}" \
          --size "${SIZE:-512x512}" --views "${VIEWS:-8}" --mappers "$mapper" ${BENCH_ARGS:-} 2>/dev/null | tail -1)
        ms[$build]=$(echo "$line" | awk -F'|' '{gsub(/ /, "", $3); print $3}')
      done
      echo "round $round $(basename "$mesh") $mapper: A ${ms[$a]} ms, B ${ms[$b]} ms, B/A" \
        "$(awk -v x="${ms[$b]}" -v y="${ms[$a]}" 'BEGIN { printf "%.3f", x / y }')"
      unset ms
    done
  done
done
