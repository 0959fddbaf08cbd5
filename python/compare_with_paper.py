#!/usr/bin/python3
"""A study side by side with a paper's published numbers (a thin wrapper of
hbtrack.paper_comparison):

    /usr/bin/python3 python/compare_with_paper.py STUDY_DIR --paper data/rotor67/paper_values.json \
        --model data/rotor67/summary.json [--reversed NFRC_DIR]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack.paper_comparison import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
