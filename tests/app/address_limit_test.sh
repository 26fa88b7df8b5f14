#!/usr/bin/env bash
# The multi-threaded commands under an address-space limit (`ulimit -v`, as a Slurm job or a
# shared machine sets it) with more threads asked for than fit in it: each thread's stack
# reserves `ulimit -s` of address space, so the system refuses some of them. The threads that
# cannot start are done without (common/worker_threads.h): every run must end as it does with
# one thread and no limit, with the same bytes, never with SIGABRT or SIGSEGV (it did, exit 134).
# The Python module alike, inside one interpreter.
#
# Usage: address_limit_test.sh FORESIGHT_BINARY [PYTHON PYTHON_MODULE_DIR]
set -euo pipefail
foresight=$(realpath "$1")
python=${2:-}
module_dir=${3:+$(realpath "$3")}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

limit_kb=1048576  # 1 GiB
threads=200
stack_kb=$(ulimit -s)
if [ "$stack_kb" = unlimited ] || (( threads * stack_kb <= limit_kb )); then
  echo "address_limit_test: $threads threads of $stack_kb kB stacks fit in $limit_kb kB; the test would not test"
  exit 1
fi

failures=0
fail() { echo "address_limit_test: $1"; failures=$((failures + 1)); }

# Runs ARGS... limited with $threads threads; fails unless the exit code is 0.
limited() {
  local name=$1
  shift
  local code=0
  ( ulimit -v "$limit_kb"; exec "$foresight" "$@" --threads "$threads" ) \
    >"$name-limited.txt" 2>"$name-limited.err" || code=$?
  if [ "$code" -ne 0 ]; then
    fail "$name: exit $code under ulimit -v $limit_kb with --threads $threads: $(head -c 300 "$name-limited.err")"
    return 1
  fi
}

# NAME ARGS...: a command that prints its result: the same bytes on stdout.
printed() {
  local name=$1
  shift
  "$foresight" "$@" --threads 1 >"$name-free.txt"
  limited "$name" "$@" || return 0
  cmp -s "$name-free.txt" "$name-limited.txt" || fail "$name: other output under the limit"
}

# NAME ARGS...: a command that writes a report folder (--out): the same files but the run time.
report() {
  local name=$1
  shift
  "$foresight" "$@" --threads 1 --out "$name-free" >/dev/null
  limited "$name" "$@" --out "$name-limited" || return 0
  bash "$root/tests/shard/same_report.sh" "$name-free" "$name-limited" ||
    fail "$name: another report under the limit"
}

situation="$root/models/situations/open_goal.json"
# The kicks play the fixed base, the cheap approximation (a tenth of a floating trial's cost):
# what is tested is the threads under the limit, not the base.
printed simulate simulate --situation "$situation" --kick forward --trials "$threads" --base fixed --json
report stability experiment stability --quick --repeats 5
report strategies experiment strategies --starts "$threads"
report passing experiment passing --config 2d --team reactive --scenarios 1 --trials "$threads"
# calibrate writes its model and its report; both compared.
"$foresight" calibrate --robot nao --kick forward --trials "$threads" --base fixed --threads 1 \
  --out calibrate-free.json >/dev/null
if limited calibrate calibrate --robot nao --kick forward --trials "$threads" --base fixed \
  --out calibrate-limited.json; then
  cmp -s calibrate-free.json calibrate-limited.json || fail "calibrate: another model under the limit"
fi

# Too little memory to read the robot's meshes is the limit's fault, not the mesh file's: at every
# limit from far too little to just enough, a run ends with the out-of-memory line or succeeds,
# never "cannot read mesh: std::bad_alloc" (which it said at 30 MB).
for mesh_kb in 20000 24000 28000 30000 32000 36000 40000 44000; do
  code=0
  ( ulimit -v "$mesh_kb"; exec "$foresight" simulate --situation "$situation" --kick forward \
    --trials 2 --base fixed --json ) >/dev/null 2>"mesh-$mesh_kb.err" || code=$?
  if grep -q "cannot read mesh" "mesh-$mesh_kb.err"; then
    fail "mesh under ulimit -v $mesh_kb: $(head -c 300 "mesh-$mesh_kb.err")"
  elif [ "$code" -ne 0 ] && ! grep -q "out of memory" "mesh-$mesh_kb.err"; then
    case "$code" in
      2) fail "mesh under ulimit -v $mesh_kb: exit 2 without the out-of-memory line: $(head -c 300 "mesh-$mesh_kb.err")" ;;
      127) ;;  # the loader could not map the program's libraries: it never ran
      *) fail "mesh under ulimit -v $mesh_kb: exit $code: $(head -c 300 "mesh-$mesh_kb.err")" ;;
    esac
  fi
done

if [ -n "$module_dir" ]; then
  code=0
  PYTHONPATH=$module_dir "$python" - "$situation" "$threads" <<'PYTHON' || code=$?
import resource, sys
import numpy as np
import foresight
situation, threads = sys.argv[1], int(sys.argv[2])
free = foresight.simulate(situation, "forward", trials=threads, seed=3, threads=1, base="fixed")
# The interpreter's own address space plus 1 GiB: room for the work, not for the threads' stacks.
with open("/proc/self/status") as status:
    vm_kb = next(int(line.split()[1]) for line in status if line.startswith("VmSize:"))
limit = (vm_kb + 1048576) * 1024
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
limited = foresight.simulate(situation, "forward", trials=threads, seed=3, threads=threads,
                             base="fixed")
for name, values in free.items():
    if isinstance(values, np.ndarray):
        assert np.array_equal(values, limited[name]), name
PYTHON
  [ "$code" -eq 0 ] || fail "python: foresight.simulate(threads=$threads) under the limit: exit $code"
fi

if [ "$failures" -ne 0 ]; then exit 1; fi
echo "address_limit_test: simulate, stability, strategies, passing, calibrate${module_dir:+ and Python} with $threads threads under ulimit -v $limit_kb: the one-thread bytes"
