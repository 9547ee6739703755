#!/usr/bin/env bash
# Paired runs, in turn: 1 thread, 2 threads, and two 1-thread renders at
# once (two processes, which share nothing but the machine): the whole
# process's wall time at 1024² (book/appendix/performance.md, "Two
# threads"). Prints per scene, as the median and the range of the runs:
#   threads:   1 thread's time / 2 threads' time;
#   processes: 2 × 1 thread's time / the two processes' time, what the
#              machine allows two workers that never wait for each other.
# Usage: book/appendix/profile/threads.sh [RUNS] [SCENE...]
# (after `cargo build --release`; scenes from scenes/spd).
set -euo pipefail
cd "$(dirname "$0")/../../.."
runs=${1:-7}
shift || true
scenes=("${@:-mount-3 teapot-6 balls-4 rings-7}")
out=$(mktemp -d)
trap 'rm -r "$out"' EXIT
render() { # THREADS OUTPUT
  target/release/raybook render "scenes/spd/$scene.nff" --width 1024 --height 1024 \
    --threads "$1" -q -o "$out/$2.png" >/dev/null 2>&1
}
seconds() { # COMMAND...: the wall time it takes
  local start
  start=$(date +%s.%N)
  "$@"
  echo "$(date +%s.%N) - $start" | bc
}
together() { render 1 a & render 1 b; wait; }
uptime
for scene in ${scenes[*]}; do
  for _ in $(seq "$runs"); do
    one=$(seconds render 1 1)
    two=$(seconds render 2 2)
    pair=$(seconds together)
    echo "$scene threads $(echo "$one / $two" | bc -l)"
    echo "$scene processes $(echo "2 * $one / $pair" | bc -l)"
    cmp -s "$out/1.png" "$out/2.png" || echo "$scene: 1 and 2 threads differ" >&2
  done
done | sort -k1,2 -k3n | awk '
  { key = $1 " " $2; r[key] = r[key] " " $3 }
  END { for (s in r) { k = split(substr(r[s], 2), v, " ");
        printf "%s: median %.2f (%.2f to %.2f)\n", s, v[int((k + 1) / 2)], v[1], v[k] } }' | sort
uptime
