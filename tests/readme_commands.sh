#!/usr/bin/env bash
# Runs every command of the README's "Using it" block as written, in a scratch folder that sees
# the source tree's examples/, python/ and data/, with the built hbtrack first on the PATH.
#   bash tests/readme_commands.sh HBTRACK_BINARY SOURCE_DIR
# Fails (naming the command) when one exits non-zero: the README's commands stay true.
set -euo pipefail
binary=$(realpath "$1")
source_dir=$(realpath "$2")
scratch=$(mktemp -d "${TMPDIR:-/tmp}/hbtrack_readme.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/bin"
ln -s "$binary" "$scratch/bin/hbtrack"
for d in examples python data; do ln -s "$source_dir/$d" "$scratch/$d"; done
# The first fenced block after "## Using it", continuation lines joined.
commands=$(awk '/^## Using it/ {section = 1} section && /^```/ {if (inside) exit; inside = 1; next} inside' "$source_dir/README.md" |
  sed -e ':join' -e '/\\$/{N; s/\\\n//; b join}')
[ -n "$commands" ] || { echo "README.md: no command block after '## Using it'" >&2; exit 1; }
cd "$scratch"
count=0
while IFS= read -r command; do
  [ -z "${command// }" ] && continue
  count=$((count + 1))
  if ! PATH="$scratch/bin:$PATH" MPLBACKEND=Agg bash -c "$command" > log.txt 2>&1; then
    echo "README command failed: $command" >&2
    tail -5 log.txt >&2
    exit 1
  fi
done <<< "$commands"
echo "$count README commands ran"
