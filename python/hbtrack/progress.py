"""The `progress` argument of the computations: checked here, called by the compiled core after
every accepted point (python/src/progress_callback.hpp) with the same fraction of the range as
the CLI's progress line."""


def checked_progress(progress):
    """`progress` when it is None or callable.

    Parameters
    ----------
    progress : callable or None
        ``progress(fraction, point, value)``; its return value False stops the computation.

    Returns
    -------
    callable or None
        `progress` itself.

    Raises
    ------
    ValueError
        When `progress` is neither None nor callable.

    Examples
    --------
    >>> checked_progress(None) is None
    True
    """
    if progress is not None and not callable(progress):
        raise ValueError(f"progress: must be callable, got {type(progress).__name__}")
    return progress
