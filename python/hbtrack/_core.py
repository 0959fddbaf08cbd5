"""The compiled part (_hbtrack, built by CMake next to this package in build/python/hbtrack).

Plotting and reading result folders work without it; computing needs it.
"""
try:
    from . import _hbtrack as core
except ImportError as error:  # the source tree without a build, or a build with HBTRACK_PYTHON=OFF
    core = None
    _import_error = error


def require_core():
    if core is None:
        raise ImportError(
            "hbtrack's compiled module _hbtrack is missing: build it (cmake --build build) and use "
            f"PYTHONPATH=build/python ({_import_error})")
    return core
