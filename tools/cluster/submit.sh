#!/bin/sh
# submit.sh: submit a prime film or a banded picture to Slurm, and the job that finishes it.
#
#   tools/cluster/submit.sh film  [TRACE_ARG...]   frames: film-array.sbatch, then finish.sbatch
#   tools/cluster/submit.sh bands [TRACE_ARG...]   bands:  bands-array.sbatch, then finish.sbatch
#
# It runs
#   sbatch --parsable --array=0-(N-1) [SBATCH_OPTS] ARRAY_SCRIPT [TRACE_ARG...]
#   sbatch --parsable --dependency=afterok:ARRAY_JOB [FINISH_OPTS] finish.sbatch
# and prints the job ids on standard output, one line each:
#   array JOBID
#   finish JOBID       (film: only when FILM is set)
# The finishing job runs once every task of the array has ended well; if one fails it never
# runs (squeue shows it pending with DependencyNeverSatisfied: scancel it, fix, resubmit).
# Variables: those of film-array.sbatch (PRIME SCENE CAMERA_PATH FIRST LAST PER_TASK OUT PNG
# THREADS) or bands-array.sbatch (PRIME SCENE ROWS BANDS PIECE PIECE_FLAG THREADS), and of
# finish.sbatch (STITCHED for bands; FILM, FPS for film). N is ceil((LAST - FIRST + 1) /
# PER_TASK) frame chunks, or BANDS. SBATCH_OPTS and FINISH_OPTS are more sbatch options,
# split at spaces (--cpus-per-task=4 --time=1:00:00); sbatch's own SBATCH_PARTITION,
# SBATCH_ACCOUNT, SBATCH_OUTPUT, ... apply to both jobs. The jobs start in the current
# directory with this environment: relative paths must name the same files on every node.
# Resume: run the same command again; frames whose .render sidecars match are skipped.
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
if ! command -v sbatch >/dev/null; then
  echo "submit: no sbatch on PATH: run this where Slurm's commands are (a login node)" >&2
  exit 2
fi
usage() {
  echo "usage: $0 film|bands [TRACE_ARG...]  (variables: see the top of $0)" >&2
  exit 2
}
[ $# -ge 1 ] || usage
MODE=$1
shift
export PRIME="${PRIME:-prime}"
case "$MODE" in
  film)
    : "${SCENE:?set SCENE}" "${CAMERA_PATH:?set CAMERA_PATH}" "${LAST:?set LAST}" "${OUT:?set OUT}"
    export FIRST="${FIRST:-0}" PER_TASK="${PER_TASK:-1}"
    if [ "$LAST" -lt "$FIRST" ] || [ "$PER_TASK" -lt 1 ]; then
      echo "submit: frames $FIRST-$LAST, $PER_TASK a task: nothing to do" >&2
      exit 2
    fi
    N=$(((LAST - FIRST + PER_TASK) / PER_TASK))
    ARRAY_SCRIPT=$HERE/film-array.sbatch
    if [ -n "${FILM:-}" ]; then
      : "${PNG:?set PNG: the film is made of the frames as PNG}"
    fi
    ;;
  bands)
    : "${SCENE:?set SCENE}" "${ROWS:?set ROWS}" "${BANDS:?set BANDS}" "${PIECE:?set PIECE}"
    : "${STITCHED:?set STITCHED (the stitched picture)}"
    if [ "$BANDS" -lt 1 ] || [ "$BANDS" -gt "$ROWS" ]; then
      echo "submit: $BANDS bands of $ROWS rows: between 1 and $ROWS bands" >&2
      exit 2
    fi
    N=$BANDS
    ARRAY_SCRIPT=$HERE/bands-array.sbatch
    ;;
  *) usage ;;
esac
export MODE
# shellcheck disable=SC2086  # SBATCH_OPTS and FINISH_OPTS are split at spaces on purpose
ARRAY_JOB=$(sbatch --parsable --array="0-$((N - 1))" ${SBATCH_OPTS:-} "$ARRAY_SCRIPT" "$@")
ARRAY_JOB=${ARRAY_JOB%%;*}  # "id;cluster" on a multi-cluster site
echo "array $ARRAY_JOB"
echo "submit: $MODE: array job $ARRAY_JOB, $N task(s)" >&2
if [ "$MODE" = film ] && [ -z "${FILM:-}" ]; then
  exit 0
fi
# shellcheck disable=SC2086
FINISH_JOB=$(sbatch --parsable --dependency="afterok:$ARRAY_JOB" ${FINISH_OPTS:-} \
  "$HERE/finish.sbatch")
FINISH_JOB=${FINISH_JOB%%;*}
echo "finish $FINISH_JOB"
echo "submit: $MODE: finishing job $FINISH_JOB after $ARRAY_JOB" >&2
