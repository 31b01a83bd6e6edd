#!/bin/bash
# Submit a LANDYN campaign as a Slurm job array plus a merge step that runs when every array
# task has ended (afterany: the merge reports missing cases rather than never running).
#
#   examples/slurm/submit_array.sh path/to/campaign.nml [CASES_PER_TASK] [MAX_RUNNING]
#
# e.g. 1000 cases, 10 per task -> 100 array tasks, at most 50 running at once.
set -euo pipefail
DECK=${1:?usage: submit_array.sh CAMPAIGN.nml [CASES_PER_TASK] [MAX_RUNNING]}
export CASES_PER_TASK=${2:-10}
MAX_RUNNING=${3:-50}
LANDYN_BATCH=${LANDYN_BATCH:-landyn_batch}
HERE=$(cd "$(dirname "$0")" && pwd)

n_cases=$(cd "$(dirname "$DECK")" && "$LANDYN_BATCH" "$(basename "$DECK")" --check |
          sed -n 's/.*: [a-z_]*, \([0-9]*\) cases.*/\1/p')
n_tasks=$(( (n_cases + CASES_PER_TASK - 1) / CASES_PER_TASK ))
echo "campaign $DECK: $n_cases cases -> $n_tasks array tasks of $CASES_PER_TASK cases"

array_id=$(sbatch --parsable --export=ALL --array="1-${n_tasks}%${MAX_RUNNING}" \
           "$HERE/campaign_array.sbatch" "$DECK")
merge_id=$(sbatch --parsable --export=ALL --dependency="afterany:${array_id}" \
           "$HERE/campaign_merge.sbatch" "$DECK")
echo "submitted array job $array_id and merge job $merge_id"
