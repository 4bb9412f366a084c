#!/usr/bin/env bash
# A constitutive table killed (SIGKILL) and interrupted (SIGTERM) part-way
# and resumed (--resume) writes the table of an uninterrupted run, row for
# row (bitwise: the points after the checkpoint are solved from the same
# state); no checkpoint is left at the end. A checkpoint of an earlier
# format version is refused (exit 1) as of another version, not misread.
# usage: robustness_strip.sh <strip> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }
table_of() {
  sed -e "s|^\( *set Output directory *=\).*|\1 $1|" -e "s|^\( *set First range *=\).*|\1 0, 1, 21|" \
      -e "s|^\( *set Second range *=\).*|\1 0, 0.2, 11|" -e "s|^\( *set Free strains *=\).*|\1 nu3|" \
      "$here/../parameter_files/strip/ribbon_comparison.prm"
}
table_of whole > whole.prm
timeout 300 "$exe" --quiet whole.prm > whole.txt 2>&1 || { bad "the uninterrupted table failed"; cat whole.txt; }
for sig in KILL TERM; do
  table_of "$sig" > "$sig.prm"
  "$exe" --quiet "$sig.prm" > "$sig-0.txt" 2>&1 & pid=$!
  for _ in $(seq 1 600); do [ -f "$sig/checkpoint.cosmo" ] && break; sleep 0.02; done
  kill -$sig $pid; wait $pid 2>/dev/null; s1=$?
  rows=$(($(wc -l < "$sig/table.csv") - 1))
  [ $sig = KILL ] && cp -r "$sig" old_format
  timeout 300 "$exe" --quiet --resume "$sig" > "$sig-1.txt" 2>&1; s2=$?
  want=$([ $sig = KILL ] && echo 137 || echo 143)
  if [ $s1 -eq "$want" ] && [ $rows -ge 1 ] && [ $rows -lt 231 ] && [ $s2 -eq 0 ] &&
     cmp -s whole/table.csv "$sig/table.csv" && [ -f "$sig/table.h5" ] && [ ! -f "$sig/checkpoint.cosmo" ] &&
     grep -q "going on after" "$sig/log.txt"; then
    ok "a table stopped by SIG$sig after $rows of 231 points and resumed: the uninterrupted table.csv"
  else bad "table SIG$sig: exits $s1 $s2, $rows rows"; cat "$sig-1.txt"; diff whole/table.csv "$sig/table.csv" | head -4; fi
done

# The killed run's checkpoint (a copy) with the format version of before
# the table's point header, 3 (the first number after the magic line).
/usr/bin/python3 -c "
import struct, sys
f = sys.argv[1]; b = bytearray(open(f, 'rb').read()); n = len(b'cosmo checkpoint\n')
assert struct.unpack_from('<Q', b, n)[0] > 3; struct.pack_into('<Q', b, n, 3); open(f, 'wb').write(b)
" old_format/checkpoint.cosmo
timeout 300 "$exe" --quiet --resume old_format > old_format.txt 2>&1; s=$?
if [ $s -eq 1 ] && grep -q "another version" old_format.txt; then
  ok "a checkpoint of format version 3 refused: exit 1, 'another version'"
else bad "a checkpoint of format version 3: exit $s"; cat old_format.txt; fi
exit $fail
