#!/usr/bin/env bash
# The passing experiment (Ros et al. 2009, sec. 5.2) on Slurm (issue 17): both teams (CBR and
# reactive, paired) against each configuration, each as a job array of N shards and its merge
# job (scripts/slurm/submit.sh):
#
#   scripts/slurm/passing.sh N OUT [ARGS...]
#   scripts/slurm/passing.sh 40 runs/passing                    the paper's 500 trials per scenario
#   CONFIGS=dg scripts/slurm/passing.sh 20 runs/passing-physics --physics --trials 100
#
# The reports appear in OUT/CONFIG/report (CONFIGS: the configurations, default "dg 2d"); ARGS
# go to every shard (and are recorded in the shard files, so the merge checks them). A shard's
# items are trials of both teams and every scenario (experiments/passing_shard.h), so N up to
# 2 teams x 4 scenarios x trials shards have work. SBATCH_ARGS and FORESIGHT as for submit.sh.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,13p' "$0"; exit 2; }
count=$1 out=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
for config in ${CONFIGS:-dg 2d}; do
  bash "$here/submit.sh" "$count" "$out/$config" experiment passing --config "$config" \
    --team both "$@"
done
