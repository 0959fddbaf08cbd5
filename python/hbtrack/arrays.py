"""Matrices handed to hbtrack: numpy arrays, nested lists, any array-like, or scipy.sparse
matrices. Sparse ones are densified where the library takes dense matrices (case files, normal
modes) and kept sparse for the Craig-Bampton reduction of a finite-element model. scipy is
imported only when a sparse matrix is given, so everything works with numpy alone."""
import numpy as np


def is_sparse(value):
    """Whether `value` is a scipy.sparse matrix or array (duck-typed: no scipy import).

    Parameters
    ----------
    value : object
        Anything.

    Returns
    -------
    bool
        True for objects with scipy.sparse's ``toarray`` and ``nnz``.

    Examples
    --------
    >>> is_sparse([[1.0]])
    False
    """
    return hasattr(value, "toarray") and hasattr(value, "nnz")


def as_matrix(value, name, *, square=True):
    """A dense float matrix from a numpy array, an array-like or a scipy.sparse matrix.

    Parameters
    ----------
    value : array_like or scipy.sparse matrix
        The matrix.
    name : str
        The argument's name, for the error message.
    square : bool, optional
        Require a square matrix (default True).

    Returns
    -------
    numpy.ndarray
        2-D float64 array.

    Raises
    ------
    ValueError
        Naming `name` when the value is not a (square) 2-D matrix of real numbers (a complex one
        is refused: the model is real, and its imaginary part would be lost silently).

    Examples
    --------
    >>> as_matrix([[2, 0], [0, 1]], "K").dtype
    dtype('float64')
    """
    if is_sparse(value):
        value = value.toarray()
    try:
        matrix = np.asarray(value)
        complex_values = np.iscomplexobj(matrix)
        if not complex_values:
            matrix = matrix.astype(float)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected a matrix of numbers, got {type(value).__name__}") from None
    if complex_values:
        raise ValueError(f"{name}: complex values (the model is real; the imaginary part would be lost)")
    if matrix.ndim != 2:
        raise ValueError(f"{name}: expected a 2-D matrix, got {matrix.ndim} dimension(s)")
    if square and matrix.shape[0] != matrix.shape[1]:
        raise ValueError(f"{name}: expected a square matrix, got {matrix.shape[0]} x {matrix.shape[1]}")
    return matrix


def as_sparse_matrix(value, name):
    """A square float matrix in scipy.sparse's compressed-column form, never densified.

    For the paths that keep a finite-element model sparse (:func:`hbtrack.reduce`); only called
    when scipy.sparse is in use, so importing it here costs numpy-only users nothing.

    Parameters
    ----------
    value : scipy.sparse matrix or array_like
        The matrix (a dense one is converted).
    name : str
        The argument's name, for the error message.

    Returns
    -------
    scipy.sparse.csc_matrix
        float64, with sorted indices.

    Raises
    ------
    ValueError
        Naming `name` when the matrix is not square or holds complex values.

    Examples
    --------
    >>> as_sparse_matrix([[2.0, 0.0], [0.0, 1.0]], "K").nnz
    2
    """
    import scipy.sparse

    if not is_sparse(value):
        value = as_matrix(value, name)
    if np.issubdtype(value.dtype, np.complexfloating):
        raise ValueError(f"{name}: complex values (the model is real; the imaginary part would be lost)")
    if value.ndim != 2 or value.shape[0] != value.shape[1]:
        raise ValueError(f"{name}: expected a square matrix, got {' x '.join(map(str, value.shape))}")
    try:
        matrix = scipy.sparse.csc_matrix(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected a matrix of numbers, got {type(value).__name__}") from None
    matrix.sum_duplicates()
    matrix.sort_indices()
    return matrix
