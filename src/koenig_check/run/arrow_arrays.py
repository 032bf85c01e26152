"""Arrow arrays to and from numpy, built on their buffers.

``pyarrow.array``, ``Array.to_numpy`` and the compute functions given a Python scalar import pandas when it
is installed (to ask whether their argument is a pandas object): a tenth to a fifth of a second, paid by
every run of the tool that makes a record table. The records are numbers, booleans and dictionary-encoded
strings without missing values, whose Arrow buffers are plain numpy memory, so they are built and read here
from their buffers, which imports nothing.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pyarrow as pa

#: The type of the records' numbers.
FLOAT64 = pa.float64()


def _numpy_type(arrow_type: pa.DataType) -> np.dtype:
    if pa.types.is_floating(arrow_type):
        return np.dtype(f"float{arrow_type.bit_width}")
    if pa.types.is_signed_integer(arrow_type):
        return np.dtype(f"int{arrow_type.bit_width}")
    if pa.types.is_unsigned_integer(arrow_type):
        return np.dtype(f"uint{arrow_type.bit_width}")
    raise TypeError(f"not a fixed-width number type: {arrow_type}")


def numbers(values: np.ndarray, arrow_type: pa.DataType = FLOAT64) -> pa.Array:
    """An Arrow array of numbers over a numpy array's memory (flattened).

    Parameters
    ----------
    values : array_like
        Converted to the numpy type of ``arrow_type`` and made contiguous (no copy when it already is).
    arrow_type : pyarrow.DataType
        An integer or floating type.

    Returns
    -------
    pyarrow.Array
    """
    flat = np.ascontiguousarray(np.asarray(values).ravel(), dtype=_numpy_type(arrow_type))
    return pa.Array.from_buffers(arrow_type, len(flat), [None, pa.py_buffer(flat)])


def booleans(values: np.ndarray) -> pa.BooleanArray:
    """An Arrow boolean array (one bit per value, least significant bit first) from a numpy mask.

    Parameters
    ----------
    values : array_like of bool

    Returns
    -------
    pyarrow.BooleanArray
    """
    flat = np.asarray(values, dtype=bool).ravel()
    bits = np.packbits(flat, bitorder="little")
    return pa.Array.from_buffers(pa.bool_(), len(flat), [None, pa.py_buffer(bits)])


def strings(words: Sequence[str]) -> pa.StringArray:
    """An Arrow string array from its UTF-8 bytes and offsets.

    Parameters
    ----------
    words : sequence of str

    Returns
    -------
    pyarrow.StringArray
    """
    text = "".join(words)
    data = text.encode("utf-8")
    offsets = np.zeros(len(words) + 1, dtype=np.int32)
    if len(data) == len(text):  # ASCII: a character is a byte
        lengths = np.fromiter(map(len, words), dtype=np.int32, count=len(words))
    else:
        lengths = np.fromiter((len(w.encode("utf-8")) for w in words), dtype=np.int32, count=len(words))
    np.cumsum(lengths, out=offsets[1:])
    return pa.Array.from_buffers(pa.string(), len(words), [None, pa.py_buffer(offsets), pa.py_buffer(data)])


def as_numpy(array: pa.Array | pa.ChunkedArray) -> np.ndarray:
    """A numpy array of an Arrow array of numbers without missing values (read-only view of one chunk).

    Parameters
    ----------
    array : pyarrow.Array or pyarrow.ChunkedArray
        Integers or floats, no nulls.

    Returns
    -------
    ndarray
        A view of the buffer for an array or a chunked array of one chunk; a concatenation otherwise.

    Raises
    ------
    ValueError
        When the array has missing values (their slots hold no number).
    """
    if isinstance(array, pa.ChunkedArray):
        if array.num_chunks == 1:
            return as_numpy(array.chunk(0))
        dtype = _numpy_type(array.type)
        return np.concatenate([as_numpy(c) for c in array.chunks]) if array.num_chunks else np.empty(0, dtype)
    if array.null_count:
        raise ValueError(f"an Arrow array of {len(array)} numbers has {array.null_count} missing")
    dtype = _numpy_type(array.type)
    if not len(array):
        return np.empty(0, dtype)
    out = np.frombuffer(array.buffers()[1], dtype=dtype, count=len(array), offset=array.offset * dtype.itemsize)
    out.flags.writeable = False  # the table's own memory: an in-place change would rewrite the records
    return out
