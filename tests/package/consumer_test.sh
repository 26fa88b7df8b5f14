#!/usr/bin/env bash
# The installable package as a robot team uses it (issue 17): install the build into a temporary
# prefix, move the installed tree elsewhere (its data must follow), build the consumer project of
# tests/package/consumer/ with find_package(foresight CONFIG REQUIRED), make one decision with the
# library and compare it with the installed `foresight decide --json` for the same seed.
#
# Usage: consumer_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
source_dir=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/installed" >/dev/null
mv "$work/installed" "$work/moved"  # an installed tree can be moved
prefix=$work/moved
data=$prefix/share/foresight/models
situation=$data/situations/near_goal_corner.json

# The moved command finds the moved data (printed as the default of --models).
"$prefix/bin/foresight" --help | grep -F -- "(default: $data)" >/dev/null ||
  { echo "consumer_test: the installed foresight does not find $data"; exit 1; }

# So does the moved Python module (its process is python3, so it looks beside the module).
if [ -d "$prefix/lib/python3/dist-packages" ]; then
  found=$(PYTHONPATH=$prefix/lib/python3/dist-packages /usr/bin/python3 -c \
    'import foresight; print(foresight.models_dir())')
  [ "$found" = "$data" ] || { echo "consumer_test: the installed module finds $found, not $data"; exit 1; }
fi

cmake -S "$source_dir/tests/package/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }

# The ground truth links and runs from the installed tree (its URDF, meshes and motions).
"$work/consumer/physics_trials" "$situation" 4 | tee "$work/physics.txt"
grep -q "^trials 4 touched [1-4] " "$work/physics.txt"

for seed in 1 7; do
  "$work/consumer/robot_decision" "$situation" "$seed" >"$work/library.json"
  "$prefix/bin/foresight" decide --situation "$situation" --seed "$seed" --json >"$work/cli.json"
  python3 - "$work/library.json" "$work/cli.json" "$seed" <<'PY'
import json, sys
lib, cli = (json.load(open(f)) for f in sys.argv[1:3])
wanted = {"kick": cli["decision"]["kick"], "rotation_deg": cli["decision"]["rotation_deg"],
          "kicks": [{k: kick[k] for k in ("name", "rotation_deg", "utility", "p_opp_goal")}
                    for kick in cli["kicks"]]}
if lib != wanted:
    sys.exit(f"consumer_test: seed {sys.argv[3]}: library {lib} != foresight decide {wanted}")
print(f"seed {sys.argv[3]}: {lib['kick']} turned {lib['rotation_deg']:.2f} deg, same as the CLI")
PY
done
