#!/usr/bin/env bash
# Grades a class on a Slurm cluster: a job array whose N tasks each grade
# a slice of the class (`grade --shard K/N`), and a merge job, started once
# every task has succeeded, that joins the slices into one gradebook and
# one report (`grade --merge`).
#
# On the cluster's login node, in the teacher's checkout of raybook (the
# reference the class is graded against), with the class on a file system
# every node sees:
#
#   CLASS=/shared/course/class OUT=/shared/course/grading \
#     bash crates/grade/teacher/slurm-grade.sh
#
# It builds grade, then submits this file as the array (each task runs it
# with `shard`) and as the merge job (`merge`, --dependency=afterok on the
# array). The outputs end up in $OUT/class: grades.csv, gradescope/,
# junit.xml, report/index.html. Slice K of N writes $OUT/shard-K-of-N/,
# with its cache inside: grade the class again after a late submission and
# each slice grades only the students whose files changed (a student's
# slice is a hash of their folder's name, which other students do not
# change).
#
# `sbatch crates/grade/teacher/slurm-grade.sh` alone runs the array below
# without the merge; `bash crates/grade/teacher/slurm-grade.sh merge`
# merges by hand.
#
# Variables (exported to the jobs, as sbatch does by default):
#   CLASS       the class folder: one folder per student (required)
#   OUT         where the slices and the outputs go (required)
#   SHARDS      N, the number of slices (default: from --array below)
#   GRADE_ARGS  more options for every slice, such as
#               "--chapters 1-3 --timeout 120" (split at spaces)
#   POINTS      the points file for the merge (default: $OUT/class/points.toml)
#   REFERENCE   the reference workspace (default: the checkout this is in)
#   GRADE       the grade binary (default: built here, target/debug/grade)
#   CACHE       one cache folder for every slice (only for slices that run
#               one after another: one grading at a time in a cache)
#   SEED        the seed every slice draws its inputs from (default: drawn
#               once by the submission, kept in $OUT/seed.txt)
#
# Every slice must be graded with the same reference, settings and seed:
# the merge refuses slices that differ, or that are missing.
#
# The array must count from 0 (Slurm's task ids); slice K is task K-1.
#SBATCH --job-name=raybook-grade
#SBATCH --array=0-7
#SBATCH --cpus-per-task=4
#SBATCH --mem-per-cpu=4G
#SBATCH --time=12:00:00
#SBATCH --output=raybook-grade-%A_%a.out

set -euo pipefail

# N: the tasks Slurm started, else SHARDS, else the --array line above.
shards_in_header() {
  local last
  last=$(sed -n 's/^#SBATCH --array=0-\([0-9][0-9]*\).*/\1/p' "$1" | head -n 1)
  echo $((${last:?"$1: no #SBATCH --array=0-M line"} + 1))
}

# Submits the array and the merge job that waits for it.
submit() {
  local script array merge
  script=$(realpath "$0")
  : "${CLASS:?set CLASS to the class folder}" "${OUT:?set OUT to the output folder}"
  CLASS=$(realpath "$CLASS")
  mkdir -p "$OUT"
  OUT=$(realpath "$OUT")
  REFERENCE=${REFERENCE:-$(cd "$(dirname "$script")/../../.." && pwd)}
  SHARDS=${SHARDS:-$(shards_in_header "$script")}
  # One seed for the whole class, kept by the teacher, never handed out.
  if [[ -z ${SEED:-} ]]; then
    SEED=$(cat "$OUT/seed.txt" 2>/dev/null || od -An -N8 -tu8 /dev/urandom | tr -d ' ')
  fi
  echo "$SEED" >"$OUT/seed.txt"
  if [[ -z ${GRADE:-} ]]; then
    (cd "$REFERENCE" && cargo build -q -p grade)
    GRADE=$REFERENCE/target/debug/grade
  fi
  export CLASS OUT SHARDS SEED REFERENCE GRADE GRADE_ARGS="${GRADE_ARGS:-}" POINTS="${POINTS:-}" CACHE="${CACHE:-}"
  array=$(sbatch --parsable --array="0-$((SHARDS - 1))" "$script" shard)
  array=${array%%;*} # "id;cluster" on a federation
  merge=$(sbatch --parsable --dependency="afterok:$array" --job-name=raybook-merge \
    --output="raybook-merge-%j.out" --wrap="bash $(printf %q "$script") merge")
  echo "submitted: slices $array (0-$((SHARDS - 1))), merge ${merge%%;*} into $OUT/class"
}

# In a job submitted without `submit` (sbatch this file): the reference is
# the folder it was submitted from (Slurm runs a copy of this file, which
# says nothing of where the checkout is), and grade is its build.
defaults() {
  REFERENCE=${REFERENCE:-${SLURM_SUBMIT_DIR:-$(cd "$(dirname "$0")/../../.." && pwd)}}
  GRADE=${GRADE:-$REFERENCE/target/debug/grade}
}

# One task of the array: slice SLURM_ARRAY_TASK_ID + 1 of
# SLURM_ARRAY_TASK_COUNT.
shard() {
  : "${SLURM_ARRAY_TASK_ID:?not a task of a job array}" "${CLASS:?}" "${OUT:?}"
  : "${SEED:=$(cat "$OUT/seed.txt")}"
  local n=${SLURM_ARRAY_TASK_COUNT:?} k=$((SLURM_ARRAY_TASK_ID + 1)) extra=()
  if [[ ${SLURM_ARRAY_TASK_MIN:-0} != 0 || ${SHARDS:-$n} != "$n" ]]; then
    echo "the array must be --array=0-$((${SHARDS:-$n} - 1)), one task a slice" >&2
    exit 2
  fi
  defaults
  read -ra extra <<<"${GRADE_ARGS:-}"
  if [[ -n ${CACHE:-} ]]; then extra+=(--cache "$CACHE"); fi
  "$GRADE" "$CLASS" --shard "$k/$n" --seed "$SEED" --out "$OUT/shard-$k-of-$n" \
    --reference "$REFERENCE" "${extra[@]}"
}

# The merge: every slice of this N, into $OUT/class.
merge() {
  : "${OUT:?}"
  local n=${SHARDS:-$(shards_in_header "$0")} extra=()
  defaults
  if [[ -n ${POINTS:-} ]]; then extra+=(--points "$POINTS"); fi
  "$GRADE" --merge "$OUT"/shard-*-of-"$n" --out "$OUT/class" \
    --reference "$REFERENCE" "${extra[@]}"
}

mode=${1:-}
if [[ -z $mode ]]; then
  if [[ -n ${SLURM_ARRAY_TASK_ID:-} ]]; then mode=shard; else mode=submit; fi
fi
case $mode in
  submit | shard | merge) "$mode" ;;
  *)
    echo "usage: bash $0 [submit|shard|merge]" >&2
    exit 2
    ;;
esac
