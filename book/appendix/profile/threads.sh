#!/usr/bin/env bash
# Paired runs, 1 thread then 2, in turn: the whole process's wall time at
# 1024² (book/appendix/performance.md, "Two threads"). Prints the ratio
# 1 thread / 2 threads per scene: the median and the range of the runs.
# Usage: book/appendix/profile/threads.sh [RUNS] [SCENE...]
# (after `cargo build --release`; scenes from scenes/spd).
set -euo pipefail
cd "$(dirname "$0")/../../.."
runs=${1:-7}
shift || true
scenes=("${@:-mount-3 teapot-6 balls-4 rings-7}")
out=$(mktemp -d)
uptime
for scene in ${scenes[*]}; do
  for _ in $(seq "$runs"); do
    for t in 1 2; do
      start=$(date +%s.%N)
      target/release/raybook render "scenes/spd/$scene.nff" --width 1024 --height 1024 \
        --threads "$t" -q -o "$out/$t.png" >/dev/null
      echo "$t $(echo "$(date +%s.%N) - $start" | bc)"
    done | paste -sd' ' | awk -v s="$scene" '{ print s, $2 / $4 }'
    cmp -s "$out/1.png" "$out/2.png" || echo "$scene: 1 and 2 threads differ" >&2
  done
done | sort -k1,1 -k2n | awk '
  { r[$1] = r[$1] " " $2; n[$1]++ }
  END { for (s in r) { k = split(substr(r[s], 2), v, " ");
        printf "%s: median %.2f (%.2f to %.2f)\n", s, v[int((k + 1) / 2)], v[1], v[k] } }'
uptime
rm -r "$out"
