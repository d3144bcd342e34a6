#!/bin/sh
# The benchmark tools refuse a bad option or value with one error naming it and exit code 2.
# Usage: bench_bad_options.sh TANDEM_VS_OMPL TANDEM_CHECK_COSTS TANDEM_OPERATOR_LOOP TANDEM_SCALING
fail=0
expect_refused() {  # TOOL NAME PATTERN ARGS...
  tool="$1" name="$2" pattern="$3"
  shift 3
  err="$("$tool" "$@" 2>&1 >/dev/null)"
  code=$?
  if [ "$code" -ne 2 ]; then
    echo "FAIL: $name $*: exit code $code, not 2 ($err)"
    fail=1
  elif ! printf '%s' "$err" | grep -q "^$name: error: .*$pattern"; then
    echo "FAIL: $name $*: the error does not name '$pattern': $err"
    fail=1
  else
    echo "ok: $name $*: $err"
  fi
}
expect_refused "$1" tandem-vs-ompl "--mode" --mode interactive
expect_refused "$1" tandem-vs-ompl "--runs" --runs zero
expect_refused "$1" tandem-vs-ompl "--bogus" --bogus
expect_refused "$2" tandem-check-costs "--bogus" --bogus
expect_refused "$3" tandem-operator-loop "--bogus" --bogus
expect_refused "$4" tandem-scaling "--only" --only planets
expect_refused "$4" tandem-scaling "--states" --states 5
expect_refused "$4" tandem-scaling "--jsonl" --only trees --nodes 10 --jsonl /nonexistent/dir/x.jsonl
"$1" --help >/dev/null || { echo "FAIL: tandem-vs-ompl --help exits $?"; fail=1; }
exit $fail
