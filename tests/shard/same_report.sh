#!/usr/bin/env bash
# Compares two report folders file by file: the same names and the same bytes, except the one
# field that may differ between two runs with the same seed, the run time ("run_time_s" in JSON,
# the "run time" row of an HTML page). Used by the shard tests (issue 17).
#
# Usage: same_report.sh WHOLE_DIR MERGED_DIR
set -euo pipefail
whole=$1 merged=$2
names() { (cd "$1" && find . -type f | sort); }
if [ "$(names "$whole")" != "$(names "$merged")" ]; then
  echo "same_report: $whole and $merged hold different files:"
  diff <(names "$whole") <(names "$merged") || true
  exit 1
fi
status=0
while IFS= read -r f; do
  if ! cmp -s <(grep -v -e '"run_time_s"' -e '>run time<' "$whole/$f") \
              <(grep -v -e '"run_time_s"' -e '>run time<' "$merged/$f"); then
    echo "same_report: $f differs between $whole and $merged:"
    diff "$whole/$f" "$merged/$f" | head -5
    status=1
  fi
done < <(names "$whole")
[ $status -eq 0 ] && echo "same_report: $(names "$whole" | wc -l) files, same bytes (run time aside)"
exit $status
