#!/usr/bin/env bash
# Submits a long foresight run to Slurm as N shards and the merge (issue 17):
#
#   scripts/slurm/submit.sh N OUT COMMAND [ARGS...]
#   scripts/slurm/submit.sh 40 runs/fidelity fidelity --situations default --trials 30
#   scripts/slurm/submit.sh 100 runs/stability experiment stability --params stability_parametric
#   scripts/slurm/submit.sh 20 runs/strategies experiment strategies --physics --starts 2000
#   scripts/slurm/submit.sh 40 runs/passing-dg experiment passing --config dg --team both
#   (scripts/slurm/passing.sh and ablations.sh submit the passing runs for both configurations)
#
# The array job (shard.sbatch, one task per shard) and the merge job (merge.sbatch, started only
# when every task succeeded: --dependency=afterok) are submitted; the report appears in
# OUT/report. OUT must be on a file system every node sees. Extra sbatch options (partition,
# time limit, CPUs per task) go in SBATCH_ARGS, e.g. SBATCH_ARGS="--partition=long
# --cpus-per-task=8". Prints the two job ids.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,18p' "$0"; exit 2; }
count=$1 out=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
# shellcheck disable=SC2086  # SBATCH_ARGS is a list of options
array=$(sbatch --parsable ${SBATCH_ARGS:-} --array=0-$((count - 1)) --chdir="$PWD" \
  --output="$out/slurm-%A_%a.out" "$here/shard.sbatch" "$count" "$out" "$@")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable ${SBATCH_ARGS:-} --dependency=afterok:"$array" --chdir="$PWD" \
  --output="$out/slurm-merge-%j.out" "$here/merge.sbatch" "$count" "$out")
merge=${merge%%;*}
echo "array job $array ($count shards), merge job $merge: report in $out/report"
