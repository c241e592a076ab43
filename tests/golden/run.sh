#!/usr/bin/env bash
# Runs every command of commands.txt with the given gyrores binary and compares what it prints
# (stdout and exit status) and the files it writes with expected/NAME (tests/golden/README.md).
#   tests/golden/run.sh BINARY            compare; exit 1 listing every difference
#   tests/golden/run.sh BINARY --update   rewrite expected/ (only with a reason in the commit)
# Run times and rates that a command prints are masked, so that only results are compared.
set -uo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ]; then echo "usage: $0 GYRORES_BINARY [--update]" >&2; exit 2; fi
bin=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
update=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mask() {
  sed -E -e 's/[0-9]+(\.[0-9]+)? s\b/<time> s/g' -e 's/\(([0-9.e+]+) (M )?pairs\/s\)/(<rate> pairs\/s)/g' \
         -e 's/("seconds": ?)[0-9.e+-]+/\1<time>/g' -e 's/"pairs_per_second": [0-9.e+-]+/"pairs_per_second": <rate>/g'
}
failed=0
count=0
while read -r name cmd; do
  case "$name" in ''|'#'*) continue ;; esac
  count=$((count + 1))
  dir="$work/$name"
  mkdir -p "$dir"
  actual="$work/$name.out"
  (cd "$dir" && cmd2="gyrores $cmd"; GYRORES="$bin" bash -c "${cmd2//gyrores /\"\$GYRORES\" }" > "$work/$name.stdout" 2> /dev/null; echo "exit $?" > "$work/$name.status")
  { echo "\$ $cmd"; cat "$work/$name.status"; mask < "$work/$name.stdout";
    (cd "$dir" && find . -type f ! -name '*.png' ! -name '*.svg' | LC_ALL=C sort | while read -r f; do
       echo "--- file ${f#./}"; mask < "$f"; done); } > "$actual"
  if [ "$update" = "--update" ]; then
    cp "$actual" "$here/expected/$name"
  elif ! diff -u "$here/expected/$name" "$actual" > "$work/$name.diff"; then
    echo "golden: $name differs:"; head -n 40 "$work/$name.diff"
    failed=$((failed + 1))
  fi
done < "$here/commands.txt"
if [ "$update" = "--update" ]; then echo "golden: $count expected outputs written"; exit 0; fi
echo "golden: $count commands, $failed differ"
[ "$failed" -eq 0 ]
