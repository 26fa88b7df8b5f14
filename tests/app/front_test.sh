#!/usr/bin/env bash
# The two executables (app/front_main.cc): `foresight` runs `decide` itself and must link none of
# the physics and robot-model libraries; every other command goes through foresight-full, and both
# ways must answer exactly as foresight-full does (output bytes, files, exit codes, errors).
#
# Usage: front_test.sh FORESIGHT FORESIGHT_FULL
set -euo pipefail
front=$(realpath "$1")
full=$(realpath "$2")
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

failures=0
fail() { echo "front_test: $1"; failures=$((failures + 1)); }

# 1. What the quick executable loads: no Bullet, assimp, urdfdom (nor what they pull in).
needed=$(readelf -d "$front" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
for lib in libBullet libLinearMath libassimp liburdfdom libconsole_bridge libtinyxml libdraco; do
  case " $needed" in *" $lib"*) fail "foresight needs $lib (DT_NEEDED: $needed)" ;; esac
done
full_needed=$(readelf -d "$full" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
case "$full_needed" in *libBullet*) ;; *) fail "foresight-full does not link Bullet: the check above would not test" ;; esac

# 2. Same answers: stdout, stderr, exit code and written files of the same command, both ways.
same() {
  local name=$1; shift
  mkdir -p "a/$name" "b/$name"
  local code_a=0 code_b=0
  (cd "a/$name" && "$front" "$@" >out 2>err) || code_a=$?
  (cd "b/$name" && "$full" "$@" >out 2>err) || code_b=$?
  # The usage line names the program as called.
  sed -i "s#$front#foresight#g" "a/$name/out" "a/$name/err"
  sed -i "s#$full#foresight#g" "b/$name/out" "b/$name/err"
  [ "$code_a" = "$code_b" ] || fail "$name: exit $code_a through foresight, $code_b from foresight-full"
  diff -r "a/$name" "b/$name" >/dev/null || fail "$name: outputs differ: $(diff -r "a/$name" "b/$name" | head -3 | tr '\n' ' ')"
}
situation=$root/models/situations/near_goal_corner.json
same decide decide --situation "$situation" --seed 7
same decide_json --models "$root/models" decide --situation "$situation" --json --strategy fast
same decide_svg decide --situation "$situation" --svg d.svg
same decide_help decide --help
same decide_bad decide --situation "$situation" --samples 0
same decide_missing decide --situation missing.json
same version --version
same help --help
same no_command
same bogus bogus
same simulate simulate --situation "$root/models/calibration/nao.json" --kick forward --trials 2 --json
same retrieve cbr retrieve --problem "$root/models/cbr/problems/$(ls "$root/models/cbr/problems" | head -1)"
[ -s a/decide_svg/d.svg ] || fail "decide --svg wrote no drawing"
grep -q "^decision:" a/decide/out || fail "decide printed no decision: $(head -c 200 a/decide/out)"

# 3. An install without foresight-full: the quick command still runs, the others fail in one line.
mkdir alone && cp "$front" alone/foresight
alone/foresight decide --situation "$situation" >/dev/null || fail "decide needs foresight-full"
code=0
alone/foresight simulate --situation x >out 2>err || code=$?
[ "$code" = 3 ] || fail "without foresight-full: exit $code, not 3"
[ "$(wc -l <err)" = 1 ] && grep -q "cannot run .*foresight-full" err ||
  fail "without foresight-full: $(head -c 300 err)"

if [ "$failures" -gt 0 ]; then echo "front_test: $failures failures"; exit 1; fi
echo "front_test: ok"
