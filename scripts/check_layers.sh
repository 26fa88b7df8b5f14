#!/usr/bin/env bash
# The layering rule of docs/ARCHITECTURE.md, checked on the sources: a file may include project
# headers only from its own folder and the folders its folder may use, and a third-party library's
# headers only where that library is private. Tests and benchmarks follow the folder they test
# (tests/planner/ as planner/), plus the test helpers in tests/support/.
#
# Usage: scripts/check_layers.sh [ROOT]   (exit 1 and one line per violation when the rule breaks)
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"

# folder -> the project folders it may include (besides itself). The table of ARCHITECTURE.md.
declare -A may_use=(
  [common]=""
  [models]="common"
  [stats]="common"
  [report]="common models"
  [planner]="common models"
  [physics]="common models stats"
  [cbr]="common models planner"
  [match]="common models planner"
  [validation]="common models stats report planner physics"
  [experiments]="common models stats report planner match cbr"
  [app]="common models stats report planner physics validation experiments cbr match"
  [tools]="common models stats report physics"
)
# The tests at the top of tests/ (every header at once) may include everything.
may_use[top]="common models stats report planner physics validation experiments cbr match app tools"
# Test helpers may use every library; benchmarks every library but the command line.
may_use[support]="common models stats report planner physics"
may_use[bench]="common models stats report planner physics validation experiments cbr match support"
may_use[fuzz]="common models stats report planner physics validation experiments cbr match"
# The Python module (python/) is a front end like app/ and returns what its commands compute.
may_use[python]="common models stats report planner physics validation experiments cbr match app"
# The consumer projects of the installed package (tests/package/consumer/): planner and physics.
may_use[package]="common models stats planner physics"

# third-party include prefix -> the only folders allowed to include it (regex on the header path)
declare -A private_to=(
  ['^(btBullet|BulletDynamics/|BulletCollision/|LinearMath/|Bullet3)']="physics"
  ['^(urdf_|urdf/|console_bridge/)']="models"
  ['^assimp/']="models"
  ['^CLI/']="app"
  ['^pybind11/']="python"
)

failures=0
fail() { echo "check_layers: $1"; failures=$((failures + 1)); }

# The folder whose rule a file follows: tests/X/... and bench/ files follow X or bench.
layer_of() {
  local path=$1 top rest
  top=${path%%/*}
  if [ "$top" = tests ]; then
    rest=${path#tests/}
    top=${rest%%/*}
    [ "$rest" = "$top" ] && top=top  # tests/*.cc at the top (all headers at once) see everything
  fi
  echo "$top"
}

while IFS= read -r file; do
  layer=$(layer_of "$file")
  if [ -z "${may_use[$layer]+set}" ]; then
    fail "$file: folder '$layer' is not in the layering table"
    continue
  fi
  allowed=" $layer ${may_use[$layer]} "
  # every test may use the test helpers; which of them it can link is the build's business
  case "$file" in tests/*) allowed="$allowed support " ;; esac
  while IFS= read -r inc; do
    [ -n "$inc" ] || continue
    folder=${inc%%/*}
    [ "$folder" = tests ] && { rest=${inc#tests/}; folder=${rest%%/*}; }
    if [ "$folder" != "$inc" ] && [ -n "${may_use[$folder]+set}" ]; then
      case "$allowed" in *" $folder "*) ;; *) fail "$file includes \"$inc\": $layer/ may not use $folder/" ;; esac
    fi
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$file")
  while IFS= read -r inc; do
    for pattern in "${!private_to[@]}"; do
      if [[ $inc =~ $pattern ]] && [ "$layer" != "${private_to[$pattern]}" ]; then
        fail "$file includes <$inc>: that library is private to ${private_to[$pattern]}/"
      fi
    done
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*<\([^>]*\)>.*/\1/p' "$file")
done < <(find . -path ./build -prune -o -path './build-*' -prune -o -path ./out -prune \
           -o -path ./.git -prune -o \( -name '*.h' -o -name '*.cc' \) -print | sed 's|^\./||' | sort)

# Every header of the project is in the all-headers translation unit (a repeated name in one
# namespace is then a compile error, not a silent ODR violation).
all_headers=tests/all_headers_test.cc
if [ -f "$all_headers" ]; then
  while IFS= read -r header; do
    grep -q "#include \"$header\"" "$all_headers" || fail "$header is missing from $all_headers"
  done < <(find common models stats report planner physics validation experiments cbr match app tools \
             -name '*.h' 2>/dev/null | sort)
else
  fail "$all_headers is missing"
fi

if [ "$failures" -gt 0 ]; then
  echo "check_layers: $failures violation(s); the table is in docs/ARCHITECTURE.md"
  exit 1
fi
echo "check_layers: ok"
