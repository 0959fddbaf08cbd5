#!/usr/bin/env bash
# Issue 39's hostile rerun against the built CLI (scripts/hostile_rerun.py; its flags pass on):
#   bash scripts/hostile-rerun.sh [--cli build/hbtrack] [--work DIR] [--seed 39] [--scale 1] [--only CLASSES]
# Prints each finding as it comes and a table of outcomes per class; exits 1 if anything was not ok.
set -euo pipefail
cd "$(dirname "$0")/.."
exec /usr/bin/python3 scripts/hostile_rerun.py "$@"
