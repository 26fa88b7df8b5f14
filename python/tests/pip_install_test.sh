#!/usr/bin/env bash
# `python3 -m pip install .` as a user runs it: a virtual environment with the system's site
# packages (Debian's NumPy), pip with no package index (--no-index: nothing is downloaded) and
# no build isolation (setuptools and wheel come from Debian), the checkout installed, then
# `import foresight` outside the checkout: the module, its stubs and its data come from the
# environment, and a Planner decides as `foresight decide` does. The build reuses BUILD_DIR
# (FORESIGHT_CMAKE_BUILD_DIR), so the test does not compile the project a second time.
#
# Usage: pip_install_test.sh SOURCE_DIR BUILD_DIR PYTHON FORESIGHT_BINARY
set -euo pipefail
source_dir=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
python=$3
binary=$(cd "$(dirname "$4")" && pwd)/$(basename "$4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$python" -m venv --system-site-packages "$work/venv"
unset PYTHONPATH
FORESIGHT_CMAKE_BUILD_DIR=$build "$work/venv/bin/python" -m pip install --no-index \
  --no-build-isolation --quiet "$source_dir" >"$work/pip.log" 2>&1 ||
  { cat "$work/pip.log"; echo "pip_install_test: pip install failed"; exit 1; }

cd "$work"  # not the checkout: nothing may come from the source tree
"$binary" decide --situation "$source_dir/models/situations/near_goal_corner.json" --seed 3 \
  --json >"$work/cli.json"
"$work/venv/bin/python" - "$work/venv" "$work/cli.json" <<'PY'
import json, pathlib, sys
venv, cli = pathlib.Path(sys.argv[1]), json.loads(pathlib.Path(sys.argv[2]).read_text())
import foresight
package = pathlib.Path(foresight.__file__).parent
assert venv in package.parents, f"foresight imported from {package}, not the environment"
for name in ("py.typed", "_foresight.pyi", "__init__.py"):
    assert (package / name).is_file(), f"{name} is not installed"
models = pathlib.Path(foresight.models_dir())
assert models == package / "models", f"the module reads {models}, not its own data"
situation = models / "situations" / "near_goal_corner.json"
planner = foresight.Planner(situation)
mine = planner.decide(seed=3).to_dict()
for run in (mine, cli):  # the same data, found in two places
    run["situation"].pop("file")
assert mine == cli, f"{mine['decision']} != {cli['decision']}"
print(f"pip-installed foresight {foresight.__version__}: {planner.decide(seed=3)}, as the CLI")
PY
"$work/venv/bin/python" -m pip uninstall --yes --quiet foresight
if "$work/venv/bin/python" -c 'import foresight' 2>/dev/null; then
  echo "pip_install_test: foresight still imports after pip uninstall"; exit 1
fi
