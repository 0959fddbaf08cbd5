#!/usr/bin/python3
"""The figures of an `hbtrack study` folder (a thin wrapper of hbtrack.study_figures, which the
study runs at its end):

    /usr/bin/python3 python/plot_study.py STUDY_DIR [--units m]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack.study_figures import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
