#!/usr/bin/env bash
# Runs every command of a page's command block as written (by default the README's "Using it";
# docs/tutorial.md's "The commands" too), in a scratch folder that sees the source tree's
# examples/, python/ and data/, with the built hbtrack first on the PATH.
#   bash tests/readme_commands.sh HBTRACK_BINARY SOURCE_DIR [PAGE HEADING]
# Fails (naming the command) when one exits non-zero: the pages' commands stay true.
set -euo pipefail
binary=$(realpath "$1")
source_dir=$(realpath "$2")
page=${3:-README.md}
heading=${4:-## Using it}
scratch=$(mktemp -d "${TMPDIR:-/tmp}/hbtrack_readme.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/bin"
ln -s "$binary" "$scratch/bin/hbtrack"
for d in examples python data; do ln -s "$source_dir/$d" "$scratch/$d"; done
# The first fenced block after the heading, continuation lines joined.
commands=$(awk -v heading="$heading" 'index($0, heading) == 1 {section = 1} section && /^```/ {if (inside) exit; inside = 1; next} inside' "$source_dir/$page" |
  sed -e ':join' -e '/\\$/{N; s/\\\n//; b join}')
[ -n "$commands" ] || { echo "$page: no command block after '$heading'" >&2; exit 1; }
cd "$scratch"
count=0
while IFS= read -r command; do
  [ -z "${command// }" ] && continue
  count=$((count + 1))
  if ! PATH="$scratch/bin:$PATH" MPLBACKEND=Agg bash -c "$command" > log.txt 2>&1; then
    echo "$page command failed: $command" >&2
    tail -5 log.txt >&2
    exit 1
  fi
done <<< "$commands"
echo "$count $page commands ran"
