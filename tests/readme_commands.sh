#!/usr/bin/env bash
# Runs a page's command blocks as written, in order, in one scratch folder that sees the source
# tree's examples/, python/ and data/, with the built hbtrack first on the PATH: by default the
# README's "Using it"; the tests name the others (README's Python and "Beyond the NFRC" blocks,
# docs/tutorial.md's "The commands").
#   bash tests/readme_commands.sh HBTRACK_BINARY SOURCE_DIR [PAGE HEADING...]
# Each heading's first fenced block (HEADING@N: its Nth): a shell block line by line (continuation lines joined), a
# ```python block as one script under /usr/bin/python3 with the build's module
# (HBTRACK_BINARY's folder/python). Fails (naming the command) when one exits non-zero: the
# pages' commands stay true.
set -euo pipefail
binary=$(realpath "$1")
source_dir=$(realpath "$2")
page=${3:-README.md}
shift $(($# < 3 ? $# : 3))
headings=("$@")
[ ${#headings[@]} -gt 0 ] || headings=("## Using it")
scratch=$(mktemp -d "${TMPDIR:-/tmp}/hbtrack_readme.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/bin"
ln -s "$binary" "$scratch/bin/hbtrack"
for d in examples python data; do ln -s "$source_dir/$d" "$scratch/$d"; done
# Pages that redraw their own figures write them here, not into the source tree.
mkdir -p "$scratch/docs/figures"
cd "$scratch"
count=0
for heading in "${headings[@]}"; do
  nth=1
  if [[ $heading =~ ^(.*)@([0-9]+)$ ]]; then heading=${BASH_REMATCH[1]} nth=${BASH_REMATCH[2]}; fi
  # The nth fenced block after the heading, its opening fence first.
  block=$(awk -v heading="$heading" -v nth="$nth" '
    index($0, heading) == 1 {section = 1}
    section && /^```/ {if (inside) {if (seen == nth) exit; inside = 0; next} inside = 1; ++seen; if (seen == nth) print; next}
    inside && seen == nth' "$source_dir/$page")
  [ -n "$block" ] || { echo "$page: no command block after '$heading'" >&2; exit 1; }
  fence=$(head -1 <<< "$block")
  body=$(tail -n +2 <<< "$block")
  if [ "$fence" = '```python' ]; then
    # A build without the Python module (the sanitizer pass: Python cannot load an instrumented
    # extension) leaves the Python blocks to the build that has it.
    if [ -n "${HBTRACK_SKIP_PYTHON_BLOCKS:-}" ]; then
      echo "$page: the Python block after '$heading' skipped: this build has no Python module"
      continue
    fi
    count=$((count + 1))
    if ! PATH="$scratch/bin:$PATH" PYTHONPATH="$(dirname "$binary")/python" MPLBACKEND=Agg /usr/bin/python3 - <<< "$body" > log.txt 2>&1; then
      echo "$page: the Python block after '$heading' failed" >&2
      tail -5 log.txt >&2
      exit 1
    fi
    continue
  fi
  commands=$(sed -e ':join' -e '/\\$/{N; s/\\\n//; b join}' <<< "$body")
  while IFS= read -r command; do
    [ -z "${command// }" ] && continue
    count=$((count + 1))
    if ! PATH="$scratch/bin:$PATH" MPLBACKEND=Agg bash -c "$command" > log.txt 2>&1; then
      echo "$page command failed: $command" >&2
      tail -5 log.txt >&2
      exit 1
    fi
  done <<< "$commands"
done
echo "$count $page commands ran"
