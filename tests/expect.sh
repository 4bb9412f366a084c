# Sourced by the bad-input scripts: expect <name> <grep pattern> <args...>
# runs "$exe" with the arguments and requires exit status 1 and a message
# matching the pattern (never an abort, a hang or a silent answer); sets
# fail=1 otherwise. Needs $exe and $fail.
expect() {
  local name=$1 pattern=$2; shift 2
  timeout 60 "$exe" "$@" > out.txt 2>&1; local status=$?
  if [ $status -eq 1 ] && grep -q -- "$pattern" out.txt; then
    echo "  ok    $name (status 1: $(grep -m1 -- "$pattern" out.txt | cut -c1-150))"
  else
    echo "  FAIL  $name: status $status (expected 1), output:"; cat out.txt; fail=1
  fi
}
