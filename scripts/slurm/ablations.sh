#!/usr/bin/env bash
# The CBR team's ablations (issue 15) on Slurm (issue 17): the reactive team and every variant of
# models/experiments/cbr_variants.json against each configuration, each as a job array of N
# shards and its merge job (scripts/slurm/submit.sh):
#
#   scripts/slurm/ablations.sh N OUT [ARGS...]
#   scripts/slurm/ablations.sh 40 runs/ablations --trials 200
#   CONFIGS=2d scripts/slurm/ablations.sh 20 runs/ablations-2d --variants my_variants.json
#
# The reports appear in OUT/CONFIG/report (CONFIGS: the configurations, default "dg 2d"); ARGS
# go to every shard (and are recorded in the shard files, so the merge checks them). A shard's
# items are trials of every team (the reactive one and 15 variants) and scenario
# (experiments/passing_shard.h). SBATCH_ARGS and FORESIGHT as for submit.sh.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,13p' "$0"; exit 2; }
count=$1 out=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
for config in ${CONFIGS:-dg 2d}; do
  bash "$here/submit.sh" "$count" "$out/$config" experiment ablations --config "$config" "$@"
done
