#!/usr/bin/env bash
# A command line formsolve cannot use: exit 1, one error line naming the
# argument, then the usage text with its own lines (not folded into the
# error line); --help prints the same text and exits 0.
# Usage: check_usage.sh FORMSOLVE
set -uo pipefail
exe=$1
fail=0
check() { # NAME EXPECTED-FIRST-LINE ARGS...
  local name=$1 first=$2; shift 2
  local err; err=$("$exe" "$@" 2>&1 >/dev/null); local rc=$?
  if [ $rc -eq 1 ] && [ "$(head -n 1 <<< "$err")" = "$first" ] &&
     grep -qx "Options:" <<< "$err" && [ "$(grep -c . <<< "$err")" -gt 5 ] &&
     [ "$(grep -c '^formsolve: error' <<< "$err")" -eq 1 ]; then
    echo "ok   $name"
  else
    echo "FAIL $name: exit $rc:"; echo "$err"; fail=1
  fi
}
check unknown_option "formsolve: error: unknown option --bogus" --bogus case.prm
check no_input "formsolve: error: no input file given"
check set_without_value 'formsolve: error: --set "Geometry": expected "Subsection/Entry=value"' \
  --set Geometry case.prm
help=$("$exe" --help); rc=$?
if [ $rc -eq 0 ] && grep -qx "Options:" <<< "$help"; then echo "ok   help"; else echo "FAIL help: exit $rc"; fail=1; fi
exit $fail
