"""What users pass, turned into what the compiled module takes, with short messages.

Every message names the argument and says what was expected; none prints an
argument's contents (a list of a million numbers would otherwise fill the
screen), so each stays well under 300 characters.
"""
import numbers
import operator

import numpy as np

_SHOWN = 40  # characters of a string or number quoted in a message

# core's sample types (isotrack/volume.h), used in place.
_CORE_DTYPES = frozenset(
    np.dtype(t) for t in (np.uint8, np.int8, np.uint16, np.int16, np.uint32, np.int32, np.float32, np.float64)
)
_EXACT_IN_FLOAT64 = 2**53


def shown(value):
    """A few words about a value for a message: never an array's or a list's contents."""
    if isinstance(value, (str, bytes)):
        text = repr(value)
        return text if len(text) <= _SHOWN else text[: _SHOWN - 4] + "...'"
    if isinstance(value, (bool, numbers.Number)):
        return repr(value)[:_SHOWN]
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    if isinstance(value, (list, tuple)):
        return f"a {type(value).__name__} of {len(value)} items"
    return "a " + type(value).__name__[:_SHOWN]


def samples_of(volume, name="volume"):
    """`volume`'s samples as a C-contiguous, aligned, native array of one of core's
    sample types, indexed (z, y, x): the array itself when it is one (no copy),
    else a converted copy of just its elements.

    bool becomes uint8 (a view when possible), float16 float32; int64 and uint64
    become int32 or uint32 when every sample fits, else float64 when every sample
    is within 2**53 (exact), else ValueError. Other real types of more than 8
    bytes (long double) are rounded to float64.
    """
    try:
        array = np.asarray(volume)
    except Exception as error:  # noqa: BLE001: numpy raises many kinds for odd objects
        raise TypeError(f"{name}: expected a 3D array, got {shown(volume)} ({type(error).__name__})") from None
    if array.ndim != 3:
        got = f"shape {array.shape}" if array.ndim or isinstance(volume, np.ndarray) else shown(volume)
        raise ValueError(f"{name}: expected a 3D array indexed (z, y, x), got {got}")
    if array.size == 0:
        raise ValueError(f"{name}: every dimension must be at least 1, got shape {array.shape}")
    kind, size = array.dtype.kind, array.dtype.itemsize
    if kind == "b":
        array = array.view(np.uint8) if array.dtype.isnative else array.astype(np.uint8)
    elif kind == "f" and size == 2:
        array = array.astype(np.float32, order="C")
    elif kind == "f" and size > 8:
        array = array.astype(np.float64, order="C")
    elif kind in "iu" and size == 8:
        array = _narrowed_integers(array, name)
    elif kind not in "iuf":
        raise ValueError(f"{name}: unsupported dtype {array.dtype} (expected a real or bool dtype)")
    if not array.dtype.isnative:
        array = array.astype(array.dtype.newbyteorder("="), order="C")
    array = np.ascontiguousarray(array)
    if not array.flags.aligned:
        array = array.copy()
    assert array.dtype in _CORE_DTYPES
    return array


def _narrowed_integers(array, name):
    """int64 or uint64 samples in the narrowest core type that holds them exactly."""
    lo, hi = int(array.min()), int(array.max())
    narrow = np.int32 if array.dtype.kind == "i" else np.uint32
    if np.iinfo(narrow).min <= lo and hi <= np.iinfo(narrow).max:
        return array.astype(narrow, order="C")
    if -_EXACT_IN_FLOAT64 <= lo and hi <= _EXACT_IN_FLOAT64:
        return array.astype(np.float64, order="C")
    raise ValueError(
        f"{name}: {array.dtype} samples from {lo} to {hi} have no exact float64 "
        "(beyond 2**53); scale them or convert them yourself"
    )


def triple(value, name, order, positive=False):
    """Three finite numbers (positive ones for spacing) as a float tuple, in the order given."""
    try:
        numbers_ = np.asarray(value, dtype=np.float64)
    except Exception:  # noqa: BLE001
        raise ValueError(f"{name}: expected three numbers {order}, got {shown(value)}") from None
    if numbers_.shape != (3,):
        raise ValueError(f"{name}: expected three numbers {order}, got shape {numbers_.shape}")
    if not np.all(np.isfinite(numbers_)) or (positive and not np.all(numbers_ > 0)):
        kind = "positive finite" if positive else "finite"
        raise ValueError(f"{name}: expected three {kind} numbers {order}, got {tuple(numbers_.tolist())}")
    return tuple(float(v) for v in numbers_)


def level_of(level):
    """None, or the level as a float (NaN and infinities are left for the module to refuse)."""
    if level is None:
        return None
    try:
        return float(level)
    except Exception:  # noqa: BLE001
        raise TypeError(f"level: expected a number or None, got {shown(level)}") from None


def integer(value, name, lowest, highest=2**31 - 1):
    """An int from lowest to highest (by default, what a C int holds)."""
    try:
        number = operator.index(value)
    except TypeError:
        try:
            number = int(value)
        except Exception:  # noqa: BLE001
            raise TypeError(f"{name}: expected an integer, got {shown(value)}") from None
    if not lowest <= number <= highest:
        raise ValueError(f"{name}: must be from {lowest} to {highest}, got {shown(number)}")
    return number


def choice(value, name, allowed):
    if not isinstance(value, str) or value not in allowed:
        raise ValueError(f"{name}: expected one of {', '.join(allowed)}, got {shown(value)}")
    return value


def step_of(step_size):
    try:
        step = int(step_size)
    except Exception:  # noqa: BLE001
        raise TypeError(f"step_size: expected an integer, got {shown(step_size)}") from None
    if step < 1:
        raise ValueError("step_size must be at least one.")
    return step


def cell_mask(mask, shape, step):
    """scikit-image's mask, one value per sample, as isotrack's mask of cells: the
    cell from sample (z, y, x) to (z+step, y+step, x+step) is marched when
    mask[z+step, y+step, x+step] is true, as scikit-image's marching cubes decides."""
    try:
        mask = np.asarray(mask)
    except Exception:  # noqa: BLE001
        raise TypeError(f"mask: expected an array, got {shown(mask)}") from None
    if mask.shape != tuple(shape):
        raise ValueError(f"volume and mask must have the same shape. (volume {tuple(shape)}, mask {mask.shape})")
    if mask.dtype.kind not in "biuf":
        raise ValueError(f"mask: unsupported dtype {mask.dtype} (expected bool)")
    return np.ascontiguousarray(mask[step::step, step::step, step::step] != 0, dtype=np.uint8)
