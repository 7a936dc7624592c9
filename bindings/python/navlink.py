"""NavLink for Python: a ctypes binding of libnavlink (standard library only).

Two layers:
- ``lib``: the C ABI as is (generated from the headers: _navlink_abi.py). Every ``nl_*`` function of
  navlink.h, recast.h and plugin.h with its prototype,
  and a ctypes.Structure per C struct (class ``MeshDef`` for ``nl_mesh_def``..., fields under their C
  names; ``C_STRUCTS`` maps C names to classes; each prints its fields by name, and fields of the
  header's kinds read as IntEnums: ``AgentInfo.state`` is an ``AgentState``...). Output structs that may
  grow start with ``size``: a new one (``Link()``...) has it set, as the header's inline ``nl_*_init()``
  does (also defined here under those names). For an output array of them the library reads the element
  size from the FIRST element: ``links = (Link * n)(); links[0] = nl_link_init()`` (ctypes arrays are
  zeroed, not constructed).
- ``World``: the world as a Python object (a context manager; ``close()`` destroys it). Failures raise
  ``NavLinkError`` with the status and the library's message; lists come back as Python lists; callbacks
  are Python callables; geometry is taken from lists (flat, or of points such as ``[(x, y, z), ...]``),
  without copying from a buffer of the C type (numpy float32 or uint32 arrays, ``array.array``,
  ``memoryview``, ``bytes``), and converted once from any other numbers (numpy float64 or int64 arrays...;
  numpy itself is never imported); a queued path is a ``PathRequest`` to wait for, await, and release with
  ``with``. States, reasons, kinds and outcomes are IntEnums (``AgentState``, ``PathOutcome``...; the
  ``AGENT_*``, ``PATH_*``... constants are their members).

The library is the first of: ``NAVLINK_LIBRARY`` (a path to libnavlink.so), the library an installed
package was built against (``pip install`` records the folder pkg-config named then, so it is found once
``PKG_CONFIG_PATH`` is gone), pkg-config's ``navlink.pc`` (its libdir), ``ctypes.util.find_library("navlink")`` (the loader's cache), the installed places
(``sys.prefix``/lib, /usr/local/lib, /usr/lib...); ``library_path`` says which was loaded, and an
ImportError lists what was tried. Every World method may be called from several threads (navlink.h);
``close()`` must not run at the same time as another call on the world.
"""
from __future__ import annotations

import collections.abc
import ctypes
import ctypes.util
import enum
import itertools
import math
import numbers
import os
import subprocess
import sys
import sysconfig
import threading
import time
from array import array as _NumberArray
from ctypes import (CFUNCTYPE, POINTER, Structure, byref, c_char_p, c_double, c_float, c_int32, c_size_t,
                    c_uint8, c_uint32, c_uint64, c_void_p, sizeof)
from typing import (TYPE_CHECKING, Any, Callable, Generator, Iterable, List, NamedTuple, Optional, Sequence, Tuple,
                    Union)

if TYPE_CHECKING:
    import asyncio

if sys.version_info >= (3, 12):
    from collections.abc import Buffer
else:
    # typing has no name for "supports the buffer protocol" before 3.12 (PEP 688).
    Buffer = Any

# ---------------------------------------------------------------------------------------------------------
# The C ABI: constants, kinds (IntEnums), structs, callback types, initialisers and prototypes, generated from
# the headers (_navlink_abi.py; bindings/generate). Kinds print by name; the AGENT_*, PATH_*... constants
# are their members.
# ---------------------------------------------------------------------------------------------------------

try:
    from ._navlink_abi import *  # noqa: F401,F403  (the installed package)
    from ._navlink_abi import PROTOTYPES as _PROTOTYPES
    from ._navlink_structs import _Growable, _Id, _read_as_enums, _shown, _Struct  # noqa: F401
except ImportError:  # navlink.py run where it is (bindings/python on sys.path)
    from _navlink_abi import *  # type: ignore[no-redef]  # noqa: F401,F403
    from _navlink_abi import PROTOTYPES as _PROTOTYPES  # type: ignore[no-redef]
    from _navlink_structs import _Growable, _Id, _read_as_enums, _shown, _Struct  # type: ignore[no-redef]  # noqa: F401

Vec3 = c_float * 3


def _navmesh_ray_init(self: Any, start: Sequence[float] = (0.0, 0.0, 0.0), start_polygon: int = 0,
                      end: Sequence[float] = (0.0, 0.0, 0.0)) -> None:
    Structure.__init__(self, Vec3(*_point(start, "start")), start_polygon, Vec3(*_point(end, "end")))


# NavmeshRay(start, start_polygon, end) takes any (x, y, z) sequences.
NavmeshRay.__init__ = _navmesh_ray_init  # type: ignore[assignment]

def succeeded(status: int) -> bool:
    return status & STATUS_SUCCESS != 0


def failed(status: int) -> bool:
    return status & STATUS_FAILURE != 0


def _outcome(value: int) -> Union[PathOutcome, int]:
    """A PathOutcome, or the number itself for an outcome newer than this module."""
    try:
        return PathOutcome(value)
    except ValueError:
        return value


def _enum_or_int(kind: Any, value: int) -> Any:
    """A member of the IntEnum `kind`, or the number itself for a value newer than this module."""
    try:
        return kind(value)
    except ValueError:
        return value


# ---------------------------------------------------------------------------------------------------------
# Structs, in header order. Fixed arrays are ctypes arrays; function pointers are CFUNCTYPE types.
# ---------------------------------------------------------------------------------------------------------

Vec3 = c_float * 3

LogFn = CFUNCTYPE(None, c_void_p, c_uint32, c_uint32, c_char_p)
# A host task system (navlink.h: nl_task_fn, nl_task_enqueue_fn, nl_task_finish_fn).
TaskFn = CFUNCTYPE(None, c_void_p, c_uint32, c_uint32, c_uint32)
TaskEnqueueFn = CFUNCTYPE(c_void_p, c_void_p, TaskFn, c_void_p, c_uint32, c_uint32)
TaskFinishFn = CFUNCTYPE(None, c_void_p, c_void_p)
ProgressFn = CFUNCTYPE(c_int32, c_void_p, c_float, c_char_p)


# ---------------------------------------------------------------------------------------------------------
# Loading the library, with every function's prototype (_PROTOTYPES, generated).
# ---------------------------------------------------------------------------------------------------------

# The library's file names, newest interface first: the versioned name is the one a runtime install has
# (Debian's libnavlink0 would ship no unversioned libnavlink.so).
_LIBRARY_FILE_NAMES = {"darwin": ["libnavlink.0.dylib", "libnavlink.dylib"],
                       "win32": ["navlink.dll"]}.get(sys.platform, ["libnavlink.so.0", "libnavlink.so"])


def _installed_library_dirs() -> List[str]:
    """Where `cmake --install` puts the library: under this Python's prefix (a virtual environment or a
    conda-like prefix installed into with --prefix), then the system's prefixes, Debian's multiarch
    folder included (GNUInstallDirs' libdir for /usr)."""
    multiarch = sysconfig.get_config_var("MULTIARCH")
    dirs = {}
    for prefix in (sys.prefix, "/usr/local", "/usr"):
        for directory in ([os.path.join(prefix, "lib", multiarch)] if multiarch else []) + [
                os.path.join(prefix, "lib"), os.path.join(prefix, "lib64")]:
            dirs.setdefault(os.path.realpath(directory), directory)  # a venv's lib64 is its lib
    return list(dirs.values())


def _built_against_library_dir() -> Optional[str]:
    """The folder pkg-config named when this package was built into a wheel (pip install), or None (the
    source tree's navlink.py, or a wheel built where pkg-config found no navlink.pc)."""
    if not __package__:
        return None
    try:
        from . import _built_against  # type: ignore[attr-defined]
    except ImportError:
        return None
    return getattr(_built_against, "LIBRARY_DIR", None)


def _pkg_config_library_dir() -> Tuple[Optional[str], str]:
    """(libdir of navlink.pc or None, what pkg-config said)."""
    try:
        run = subprocess.run(["pkg-config", "--print-errors", "--variable=libdir", "navlink"], capture_output=True, text=True,
                             timeout=30)
    except (OSError, subprocess.SubprocessError) as e:
        return None, "pkg-config did not run (%s)" % e
    libdir = run.stdout.strip()
    if run.returncode != 0 or not libdir:
        said = " ".join(run.stderr.split()) or "exit status %d" % run.returncode
        return None, "no navlink.pc (%s)" % said
    return libdir, "libdir %s" % libdir


def _library_candidates() -> Iterable[Tuple[str, Optional[str], str]]:
    """(how it was found, path or loader name to try or None, note) in the order of the lookup."""
    explicit = os.environ.get("NAVLINK_LIBRARY")
    if explicit:
        yield "NAVLINK_LIBRARY", explicit, ""
        return  # an explicit choice that fails must not be papered over by another library
    yield "NAVLINK_LIBRARY", None, "not set"
    built_against = _built_against_library_dir()
    if built_against:
        paths = [os.path.join(built_against, name) for name in _LIBRARY_FILE_NAMES]
        for path in [p for p in paths if os.path.exists(p)]:
            yield "the library this package was installed against", path, ""
        if not any(os.path.exists(p) for p in paths):
            yield "the library this package was installed against", None, "%s holds none of %s" % (
                built_against, ", ".join(_LIBRARY_FILE_NAMES))
    libdir, said = _pkg_config_library_dir()
    found_in_libdir = False
    for name in _LIBRARY_FILE_NAMES if libdir else []:
        path = os.path.join(libdir, name)
        if os.path.exists(path):
            found_in_libdir = True
            yield "pkg-config navlink", path, said
    if not found_in_libdir:
        yield "pkg-config navlink", None, said if libdir is None else "%s holds none of %s" % (
            said, ", ".join(_LIBRARY_FILE_NAMES))
    name = ctypes.util.find_library("navlink")
    yield 'ctypes.util.find_library("navlink")', name, "" if name else "found nothing"
    for directory in _installed_library_dirs():
        for file_name in _LIBRARY_FILE_NAMES:
            path = os.path.join(directory, file_name)
            if os.path.exists(path):
                yield "installed", path, ""
    yield "installed", None, "none of %s in %s" % (", ".join(_LIBRARY_FILE_NAMES),
                                                   ", ".join(_installed_library_dirs()))


def _open_library() -> Tuple[ctypes.CDLL, str]:
    """The first candidate that loads, with its path; ImportError listing every attempt otherwise."""
    attempts = []
    for how, path, note in _library_candidates():
        if path is None:
            attempts.append("%s: %s" % (how, note))
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as e:
            attempts.append("%s: %s did not load (%s)" % (how, path, e))
    raise ImportError(
        "navlink: libnavlink not found. Tried, in order:\n  " + "\n  ".join(attempts) +
        "\nInstall NavLink (cmake --install build, or --prefix somewhere), then set PKG_CONFIG_PATH to the "
        "folder of its navlink.pc (PREFIX/lib/pkgconfig) unless pkg-config finds it already, or set "
        "NAVLINK_LIBRARY to the path of libnavlink.so.", name="navlink")


def _load_library() -> Tuple[ctypes.CDLL, str]:
    library, path = _open_library()
    for name, (restype, argtypes) in _PROTOTYPES.items():
        try:
            function = getattr(library, name)
        except AttributeError:
            raise ImportError("navlink: %s has no %s: the library is older than this binding (%d.%d.%d)" % (
                path, name, VERSION_MAJOR, VERSION_MINOR, VERSION_PATCH), name="navlink") from None
        function.restype = restype
        function.argtypes = argtypes
    return library, path


lib, library_path = _load_library()


# ---------------------------------------------------------------------------------------------------------
# Statuses as exceptions
# ---------------------------------------------------------------------------------------------------------


class NavLinkError(Exception):
    """A failed call: its nl_status and the library's message (the calling thread's last error)."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__("%s (%s)" % (message, status_string(status)))
        self.status = status
        self.message = message

    def has(self, bit: int) -> bool:
        return self.status & bit != 0


def status_string(status: int) -> str:
    """nl_status_string: "failure: invalid argument"."""
    return lib.nl_status_string(status).decode()


def last_error_message() -> str:
    """The calling thread's last error message (read right after the failing call)."""
    return lib.nl_get_last_error_message().decode("utf-8", "replace")


def _check(status: int) -> int:
    if failed(status):
        raise NavLinkError(status, last_error_message())
    return status


def _buffer_too_small(status: int) -> bool:
    return failed(status) and status & STATUS_BUFFER_TOO_SMALL != 0


def _growable_array(item_type: Any, count: int) -> Any:
    """A zeroed ctypes array; for growable elements, the first has `size` set (the library's stride)."""
    items = (item_type * count)()
    if count > 0 and isinstance(item_type, type) and issubclass(item_type, _Growable):
        items[0] = item_type()
    return items


def _two_call(call: Callable[[Any, int, Any], int], item_type: Any) -> list:
    """The header's two-call pattern: count, then fill. The list may grow in between: ask again."""
    while True:
        count = c_uint32(0)
        _check(call(None, 0, byref(count)))
        items = _growable_array(item_type, count.value)
        if count.value == 0:
            return []
        status = call(items, count.value, byref(count))
        if _buffer_too_small(status):
            continue
        _check(status)
        return list(items[:count.value])


# ---------------------------------------------------------------------------------------------------------
# Arrays handed to C: lists and tuples (flat or of rows) are converted; buffers of the C type (numpy arrays,
# array.array, memoryview, bytes) are read in place, as the library copies what it keeps before the call
# returns; buffers of other numbers are converted once.
# ---------------------------------------------------------------------------------------------------------

FloatValues = Union[Sequence[float], Sequence[Sequence[float]], Buffer]  # flat, in rows, or a buffer
IndexValues = Union[Sequence[int], Sequence[Sequence[int]], Buffer]
ByteValues = Union[Sequence[int], Buffer]
Point = Union[Sequence[float], Buffer]  # x y z
LogHandler = Callable[[int, int, str], None]  # (level, status, message)
ProgressHandler = Callable[[float, str], Any]  # (fraction, stage) -> false to cancel
PathHandler = Callable[["PathTicket", Union["PathOutcome", int]], None]  # (ticket, outcome)

# A buffer's items each C type takes in place, by struct code (numpy float32 'f', uint32 'I', int32 'i'; 'L'
# and 'l' where long is 4 bytes); a buffer of raw bytes is taken for any type, as that type's items in native
# order. Any other numbers (numpy float64, int64, uint16..., array('d'), a strided or byte-swapped view,
# nested lists of points) are converted once, to the array.array of the C type's code: floats to 32-bit
# floats, integers to 32-bit unsigned ones (or bytes) with their range checked.
_IN_PLACE_FORMATS = {c_float: "f", c_uint32: "IiLl", c_uint8: "Bbc"}
_ARRAY_CODES = {c_float: "f", c_uint32: "I", c_uint8: "B"}
_EXPECTED = {c_float: "numbers", c_uint32: "integers from 0 to 4294967295", c_uint8: "integers from 0 to 255"}
_RAW_BYTE_FORMATS = "Bbc"
_NATIVE_ORDER_PREFIXES = "@=" + ("<" if sys.byteorder == "little" else ">")
_NUMBER_CODES = "bBhHiIlLqQfd"  # the struct codes array.array reads from bytes (in native sizes)


class _CArray(NamedTuple):
    items: Any  # a ctypes array over the caller's buffer when it is writable, else a copy
    count: int  # its items
    row: int    # items per row: a 2-D buffer's (or nested rows') last dimension, else the group asked for


def _c_array(name: str, values: Any, item: Any, group: int = 1, wider_rows: bool = False,
             length: Optional[int] = None) -> _CArray:
    """`values` as a ctypes array of `item` for C to read, named `name` in errors. A multiple of `group`
    items (rows of `group` in a 2-D buffer or in nested sequences; of `group` or more with wider_rows, the
    row's length given back for the C stride; with group 1, rows of any length are read one after the
    other), or exactly `length`. Taken: lists and tuples of numbers or of rows of numbers ([x, y, z]
    lists or tuples, numpy rows...); any buffer, read in place when its items are the C type's, else
    converted once; an object with tolist() (an array-like without the buffer protocol); another iterable."""
    if isinstance(values, (list, tuple)):
        return _from_numbers(name, values, item, group, wider_rows, length)
    if isinstance(values, str):
        raise TypeError("%s: numbers expected (a list, a tuple, rows of them or a buffer), not str" % name)
    try:
        view = memoryview(values)
    except TypeError:
        view = None
    if view is not None:
        in_place = _buffer_in_place(name, view, item, group, wider_rows, length)
        if in_place is not None:
            return in_place
        numbers, rows_of = _buffer_numbers(name, view, values)
        return _from_numbers(name, numbers, item, group, wider_rows, length, rows_of)
    tolist = getattr(values, "tolist", None)
    if callable(tolist):
        listed = tolist()
        return _from_numbers(name, listed if isinstance(listed, (list, tuple)) else [listed], item, group,
                             wider_rows, length)
    if isinstance(values, collections.abc.Iterable) and not isinstance(values, (dict, set, frozenset)):
        return _from_numbers(name, list(values), item, group, wider_rows, length)
    raise TypeError("%s: numbers expected: a list or tuple (flat, or of rows such as [x, y, z]), a buffer (numpy "
                    "array, array.array, memoryview, bytes) or an array with tolist(), not %s" % (
                        name, type(values).__name__))


def _rows_checked(name: str, row: int, group: int, wider_rows: bool, shape: Any = None) -> int:
    """The row length C reads with: `row` (a 2-D buffer's or nested rows' last dimension) when it fits the
    group, the group for group 1 (rows read one after the other); ValueError otherwise."""
    if group == 1:
        return 1
    if row != group and not (wider_rows and row > group):
        given = "a buffer of shape %s" % (tuple(shape),) if shape is not None else "rows of %d values" % row
        raise ValueError("%s: %s; rows of %d%s expected" % (name, given, group, " or more" if wider_rows else ""))
    return row


def _buffer_in_place(name: str, view: memoryview, item: Any, group: int, wider_rows: bool,
                     length: Optional[int]) -> Optional[_CArray]:
    """A buffer whose items are the C type's (or raw bytes) as a ctypes array over it (a copy when it is
    read-only, strided or misaligned); None for other numbers, to be converted."""
    size = sizeof(item)
    raw = view.format in _RAW_BYTE_FORMATS
    if not raw and (view.format.lstrip(_NATIVE_ORDER_PREFIXES) not in _IN_PLACE_FORMATS[item]
                    or view.itemsize != size):
        return None
    if view.nbytes % size:
        raise ValueError("%s: %d bytes, not a whole number of %d-byte items" % (name, view.nbytes, size))
    row = group
    if view.ndim > 1 and not raw:
        row = _rows_checked(name, view.shape[-1], group, wider_rows, view.shape)
    count = view.nbytes // size
    if not view.c_contiguous:
        # A strided view (a numpy slice, a transposed array): its items in C order, one copy.
        items = (item * count).from_buffer_copy(view.tobytes())
    elif view.readonly:
        # ctypes hands C a pointer only into writable memory: one copy.
        items = (item * count).from_buffer_copy(view.cast("B"))
    else:
        flat = view.cast("B")
        items = (item * count).from_buffer(flat)
        if ctypes.addressof(items) % ctypes.alignment(item):
            items = (item * count).from_buffer_copy(flat)  # a slice at an odd offset: C needs aligned items
    return _checked_length(name, _CArray(items, count, row), row, length)


def _buffer_numbers(name: str, view: memoryview, values: Any) -> Tuple[Any, Optional[int]]:
    """A buffer of other numbers, read: (an array.array of its items in C order and the length of its rows,
    or None for a flat one) when array.array reads its format, else (its tolist(): nested lists, None)."""
    code = view.format.lstrip(_NATIVE_ORDER_PREFIXES)
    if len(code) == 1 and code in _NUMBER_CODES and _NumberArray(code).itemsize == view.itemsize:
        items = _NumberArray(code)
        items.frombytes(view.tobytes() if not view.c_contiguous else view.cast("B"))
        return items, view.shape[-1] if view.ndim > 1 else None
    try:
        return view.tolist(), None  # half floats, bools...
    except (NotImplementedError, TypeError, ValueError):
        tolist = getattr(values, "tolist", None)  # a byte-swapped numpy array: numpy reads it
        if callable(tolist):
            return tolist(), None
    raise TypeError("%s: numbers expected, not a buffer of format %r (%d bytes an item)" % (
        name, view.format, view.itemsize))


def _from_numbers(name: str, values: Any, item: Any, group: int, wider_rows: bool, length: Optional[int],
                  rows_of: Optional[int] = None) -> _CArray:
    """Numbers as a C array of `item`, converted once (an array.array of its code; ints out of the C type's
    range and floats for integers refused): `values` flat, or rows of numbers (lists, tuples, numpy rows,
    Vec3s...), flattened; rows_of: the rows' length of flat `values` read from a 2-D buffer."""
    if rows_of is None and len(values) and not isinstance(values[0], numbers.Number):
        rows = values if set(map(type, values)) <= {list, tuple} else [_row(name, r) for r in values]
        lengths = sorted(set(map(len, rows)))
        if group > 1 and len(lengths) > 1:
            raise ValueError("%s: rows of %s values; rows of one length (%d%s) expected" % (
                name, " and ".join(str(n) for n in lengths), group, " or more" if wider_rows else ""))
        rows_of = lengths[-1] if lengths else None
        values = [c for r in rows for c in r]
    row = group if rows_of is None else _rows_checked(name, rows_of, group, wider_rows)
    try:
        converted = _NumberArray(_ARRAY_CODES[item], values)
    except OverflowError as e:
        raise ValueError("%s: %s expected (%s)" % (name, _EXPECTED[item], e)) from None
    except TypeError as e:
        raise TypeError("%s: %s expected (%s)" % (name, _EXPECTED[item], e)) from None
    count = len(converted)
    items = (item * count).from_buffer(converted) if count else (item * 0)()
    return _checked_length(name, _CArray(items, count, row), row, length)


def _row(name: str, row: Any) -> Sequence[Any]:
    """One row of nested input (a point's x y z, a triangle's corners) as a sequence of numbers."""
    if isinstance(row, (list, tuple)):
        return row
    if isinstance(row, (str, bytes)):
        raise TypeError("%s: numbers or rows of numbers expected, not %s" % (name, type(row).__name__))
    tolist = getattr(row, "tolist", None)
    if callable(tolist):
        listed = tolist()
        if isinstance(listed, list):
            return listed
    try:
        return list(row)
    except TypeError:
        raise TypeError("%s: numbers or rows of numbers expected, not %s" % (name, type(row).__name__)) from None


def _checked_length(name: str, array: _CArray, row: int, length: Optional[int]) -> _CArray:
    if length is not None and array.count != length:
        raise ValueError("%s: %d values, %d expected" % (name, array.count, length))
    if array.count % row:
        raise ValueError("%s: %d values, not a multiple of %d" % (name, array.count, row))
    return array


def _floats(values: FloatValues, name: str = "values", length: Optional[int] = None) -> Any:
    return _c_array(name, values, c_float, length=length).items


def _point(values: FloatValues, name: str) -> Any:
    """An x y z point for C (it reads three floats)."""
    return _floats(values, name, length=3)


def _points(name: str, points: Union[Sequence[Sequence[float]], FloatValues]) -> _CArray:
    """Points as (x, y, z) sequences, flat x y z values, or a buffer of them."""
    return _c_array(name, points, c_float, group=3)


def _pointer(array: _CArray, item: Any) -> Any:
    return ctypes.cast(array.items, POINTER(item))


def version() -> Tuple[int, int, int]:
    """The loaded library's version as (major, minor, patch)."""
    v = lib.nl_get_version()
    return (v.major, v.minor, v.patch)


# ---------------------------------------------------------------------------------------------------------
# Callbacks: one module-level trampoline per type (ctypes keeps them alive here), the Python callable found
# through `user`, a key into a registry. Exceptions never reach C: they are printed (log, path) or carried
# back to the caller (progress).
# ---------------------------------------------------------------------------------------------------------

_registry: dict = {}
_registry_lock = threading.Lock()
_keys = itertools.count(1)


def _register(obj: Any) -> int:
    with _registry_lock:
        key = next(_keys)
        _registry[key] = obj
        return key


def _lookup(key: int, remove: bool = False) -> Any:
    with _registry_lock:
        return _registry.pop(key, None) if remove else _registry.get(key)


def _report(what: str) -> None:
    import traceback
    print("navlink: %s raised (ignored):" % what)
    traceback.print_exc()


@LogFn
def _log_trampoline(user, level, status, message):
    try:
        _lookup(user)(level, status, message.decode("utf-8", "replace"))
    except Exception:
        _report("the log callback")


class _ProgressContext:
    def __init__(self, handler: ProgressHandler) -> None:
        self.handler = handler
        self.error: Optional[BaseException] = None


@ProgressFn
def _progress_trampoline(user, fraction, stage):
    context = _lookup(user)
    if context.error is not None:
        return 0
    try:
        return 1 if context.handler(fraction, stage.decode()) else 0
    except BaseException as e:  # cancel the call (a generation, a build); raised again by the caller
        context.error = e
        return 0


class _PathCompletion:
    """What a queued request's callback tells: the caller's on_finished, then the asyncio futures awaiting
    it, each woken on its own loop. Apart from the PathRequest, so that the registry holding it until the
    callback runs does not keep the PathRequest (and its release on __del__) alive."""

    def __init__(self, on_finished: Optional[PathHandler]) -> None:
        self.on_finished = on_finished
        self.outcome: Optional[Union[PathOutcome, int]] = None
        self._lock = threading.Lock()
        self._waiters: List[Tuple[asyncio.AbstractEventLoop, asyncio.Future]] = []

    def finish(self, ticket: PathTicket, outcome: Union[PathOutcome, int]) -> None:
        if self.on_finished is not None:
            try:
                self.on_finished(ticket, outcome)
            except Exception:
                _report("a path callback")
        with self._lock:
            self.outcome = outcome
            waiters, self._waiters = self._waiters, []
        for loop, future in waiters:
            try:
                loop.call_soon_threadsafe(_settle, future, outcome)
            except RuntimeError:
                pass  # that loop is closed: nobody is awaiting there any more

    def add_waiter(self, loop: asyncio.AbstractEventLoop, future: asyncio.Future) -> None:
        with self._lock:
            if self.outcome is None:
                self._waiters.append((loop, future))
                return
        future.set_result(self.outcome)


def _settle(future: asyncio.Future, outcome: Union[PathOutcome, int]) -> None:
    if not future.done():  # the awaiting task may have been cancelled meanwhile
        future.set_result(outcome)


@PathCallback
def _path_trampoline(user: int, ticket: PathTicket, outcome: int) -> None:
    # navlink.h: called exactly once per accepted request, so the entry goes.
    _lookup(user, remove=True).finish(PathTicket(ticket.index1, ticket.revision), _outcome(outcome))


def _with_progress(progress: Optional[ProgressHandler], call: Callable[[Any, Any], int]) -> int:
    if progress is None:
        return _check(call(ProgressFn(), None))
    context = _ProgressContext(progress)
    key = _register(context)
    try:
        status = call(_progress_trampoline, key)
        message = last_error_message()
    finally:
        _lookup(key, remove=True)
    if context.error is not None:
        raise context.error
    if failed(status):
        raise NavLinkError(status, message)
    return status


# ---------------------------------------------------------------------------------------------------------
# Defaults
# ---------------------------------------------------------------------------------------------------------


def default_agent_type() -> AgentType:
    return lib.nl_default_agent_type()


def default_recast_settings() -> RecastSettings:
    return lib.nl_default_recast_settings()


def default_link_def() -> LinkDef:
    """A manual one-way link, enabled, cost modifier 1, requirements measured from its ends, within one navmesh
    (landing_navmesh null; tolerance 0.25 for when it is set): set start and end."""
    return lib.nl_default_link_def()


def default_link_settings() -> LinkSettings:
    return lib.nl_default_link_settings()


def default_navmesh_load_def() -> NavmeshLoadDef:
    """The null carrier and no flags: a NavmeshLoadDef for a raw nl_navmesh_load (World.load_navmesh takes
    carrier and same_level instead)."""
    return lib.nl_default_navmesh_load_def()


def describe_navmesh_file(data: ByteValues) -> Tuple[NavmeshFileInfo, str]:
    """Reads a navmesh file's bytes (any buffer) without loading it (nl_navmesh_file_describe; no world
    needed): returns (NavmeshFileInfo, made-for JSON string), the JSON an object {"builder",
    "builder_settings", "link_settings", "link_plugins", "level_hash", "writer"}. STATUS_VERSION_MISMATCH
    (not a NavLink navmesh file, or a newer format), STATUS_PARSE_ERROR (truncated or corrupted)."""
    file = _c_array("data", data, c_uint8)
    info = NavmeshFileInfo()
    info.size = sizeof(NavmeshFileInfo)
    length = c_size_t()
    _check(lib.nl_navmesh_file_describe(file.items, file.count, byref(info), None, 0, byref(length)))
    buffer = ctypes.create_string_buffer(length.value + 1)
    _check(lib.nl_navmesh_file_describe(file.items, file.count, None, buffer, len(buffer), byref(length)))
    return info, buffer.raw[:length.value].decode()


def default_agent_capabilities() -> AgentCapabilities:
    return lib.nl_default_agent_capabilities()


def default_path_budget() -> PathBudget:
    """No limits: a PathBudget to change the fields of (World.process_paths takes one as `budget`)."""
    return lib.nl_default_path_budget()


def default_agent_def() -> AgentDef:
    """A walker, height 2, speed 3.5, acceleration 8, gravity 9.81, avoidance on, never giving
    up (give_up_seconds 0), on the null navmesh at the origin: set navmesh and position."""
    return lib.nl_default_agent_def()


def link_settings_from_json(json: str, base: Optional[LinkSettings] = None) -> LinkSettings:
    """Applies a JSON object's keys to `base` (the defaults when None) and validates the result."""
    settings = LinkSettings.from_buffer_copy(base if base is not None else default_link_settings())
    data = json.encode()
    _check(lib.nl_link_settings_from_json(data, len(data), byref(settings)))
    return settings


class PathQuery:
    """One path request, with nl_default_path_request_def's defaults. start, goal: x y z (a tuple, a list, a
    numpy array of any float type...). area_costs: cost per metre walked in area i (a list or a buffer of
    numbers)."""

    def __init__(self, navmesh: NavmeshId, start: Point, goal: Point, capabilities: AgentCapabilities) -> None:
        d = lib.nl_default_path_request_def()
        self.navmesh = navmesh
        self.start: Tuple[float, ...] = tuple(start)
        self.goal: Tuple[float, ...] = tuple(goal)
        _point(self.start, "start"), _point(self.goal, "goal")  # refused here rather than when planned
        self.search_half_extents: Tuple[float, ...] = tuple(d.search_half_extents)
        self.capabilities = capabilities
        self.area_costs: FloatValues = []
        self.link_cost: float = d.link_cost
        self.max_nodes: int = d.max_nodes
        self.accept_partial: bool = d.accept_partial != 0

    def _def(self) -> Tuple[PathRequestDef, _CArray]:
        d = lib.nl_default_path_request_def()
        d.navmesh = self.navmesh
        d.start = _point(self.start, "start")
        d.goal = _point(self.goal, "goal")
        d.search_half_extents = _point(self.search_half_extents, "search_half_extents")
        d.capabilities = self.capabilities
        costs = _c_array("area_costs", self.area_costs, c_float)
        d.area_costs = _pointer(costs, c_float) if costs.count else None
        d.area_cost_count = costs.count
        d.link_cost = self.link_cost
        d.max_nodes = self.max_nodes
        d.accept_partial = 1 if self.accept_partial else 0
        return d, costs  # the caller keeps `costs` alive for the call


class QueryFilter:
    """The body a navmesh query is for (nl_query_filter), as a PathQuery describes it: its capabilities
    (default_agent_capabilities() when None: a walker of radius 0.6) and its area costs, cost per metre in
    area i (a list or a buffer of 32-bit floats, at most 256): an area of cost AREA_EXCLUDED is kept out of;
    other costs do not matter to these queries. QueryFilter() is nl_default_query_filter()."""

    def __init__(self, capabilities: Optional[AgentCapabilities] = None, area_costs: FloatValues = ()) -> None:
        self.capabilities = (capabilities if capabilities is not None
                             else lib.nl_default_query_filter().capabilities)
        self.area_costs: FloatValues = area_costs

    def _def(self) -> Tuple[QueryFilterDef, _CArray]:
        d = lib.nl_default_query_filter()
        d.capabilities = self.capabilities
        costs = _c_array("area_costs", self.area_costs, c_float)
        d.area_costs = _pointer(costs, c_float) if costs.count else None
        d.area_cost_count = costs.count
        return d, costs  # the caller keeps `costs` alive for the call


def default_query_filter() -> QueryFilter:
    """A walker of radius 0.6 that keeps out of no area (nl_default_query_filter)."""
    return QueryFilter()


def _filter_def(query_filter: Optional[QueryFilter]) -> Tuple[Any, Any]:
    """A filter for C (None: NULL, the default filter) and what must stay alive for the call."""
    if query_filter is None:
        return None, None
    d, costs = query_filter._def()
    return byref(d), (d, costs)


class NavmeshTile(NamedTuple):
    """Where a host's navmesh polygons go as one tile of a tiled navmesh (nl_navmesh_def's tile fields): tile
    (x, z) of a grid of squares `width` metres wide on the x-z plane whose tile (0, 0) has its lower corner at
    `origin` (x, z); the tile spans x in [origin[0] + x * width, + width] and z alike. A navmesh's grid is
    navmesh_info(...).tile_width and tile_origin (a build with RecastSettings.tile_size makes one)."""
    x: int
    z: int
    width: float
    origin: Tuple[float, float] = (0.0, 0.0)


TileLike = Union[TileCoord, Tuple[int, int], NavmeshTile]  # a tile's place: TileCoord, (x, z) or a NavmeshTile


def _tile_coord(tile: TileLike) -> TileCoord:
    if isinstance(tile, TileCoord):
        return tile
    x, z = tile[0], tile[1]
    return TileCoord(x, z)


class FinishedPath(NamedTuple):
    """A request that finished, as World.take_finished_paths reports it."""
    ticket: PathTicket
    outcome: Union[PathOutcome, int]


class PathResult:
    """What a finished request found: `info` (nl_path_result) and its `points` (PathPoints), with info's
    figures read as attributes: outcome (a PathOutcome), length and cost (of the path found), links_used,
    nodes_visited, out_of_nodes, status, start and goal (snapped to the navmesh), and positions (each
    point's (x, y, z)). Prints as PathResult(outcome=COMPLETE, length=58.90 m, points=12, links=1)."""

    def __init__(self, info: PathResultInfo, points: List[PathPoint]) -> None:
        self.info = info
        self.points = points

    @property
    def outcome(self) -> Union[PathOutcome, int]:
        return _outcome(self.info.outcome)

    @property
    def length(self) -> float:
        """Metres walked, from point to point along the navmesh surface (a link's straight chord)."""
        return self.info.length

    @property
    def cost(self) -> float:
        """What the path costs: its metres seen from above times each area's cost, plus the links' costs."""
        return self.info.cost

    @property
    def links_used(self) -> int:
        return self.info.links_used

    @property
    def nodes_visited(self) -> int:
        return self.info.nodes_visited

    @property
    def out_of_nodes(self) -> bool:
        """The search stopped at max_nodes."""
        return self.info.out_of_nodes != 0

    @property
    def status(self) -> int:
        """For PATH_FAILED, the nl_status saying why; STATUS_SUCCESS otherwise."""
        return self.info.status

    @property
    def start(self) -> Tuple[float, float, float]:
        """The start snapped to the navmesh."""
        return tuple(self.info.start)  # type: ignore[return-value]

    @property
    def goal(self) -> Tuple[float, float, float]:
        """The goal snapped to the navmesh (where the path ends if COMPLETE)."""
        return tuple(self.info.goal)  # type: ignore[return-value]

    @property
    def positions(self) -> List[Tuple[float, float, float]]:
        """Each point's position as an (x, y, z) tuple."""
        return [tuple(p.position) for p in self.points]  # type: ignore[misc]

    def __repr__(self) -> str:
        return "PathResult(outcome=%s, length=%.2f m, points=%d, links=%d)" % (
            getattr(self.outcome, "name", self.outcome), self.length, len(self.points), self.links_used)


class PathShortfall:
    """Why a request's path falls short of its goal (World.explain_path): `info` (nl_path_shortfall) read as
    Python values. reason: a PathShortfallReason (NONE when the path reaches the goal or an end is off the
    navmesh); limit: a LinkLimit, for LINK_BEYOND_BODY; needed, has: metres (LINK_BEYOND_BODY: what the link
    needs and what the body can, for WIDTH the body's diameter and the link's clearance; BODY_TOO_WIDE: the
    body's radius and the navmesh's); reversed; missing_abilities (LINK_LIMIT_ABILITIES); link (a LinkId, null
    but for LINK_BEYOND_BODY) and link_start (where the body would take it); text: the same as a sentence
    naming the field to change ("" for NONE)."""

    def __init__(self, info: PathShortfallInfo) -> None:
        self.info = info
        self.reason: Union[PathShortfallReason, int] = _enum_or_int(PathShortfallReason, info.reason)
        self.limit: Union[LinkLimit, int] = _enum_or_int(LinkLimit, info.limit)
        self.needed: float = info.needed
        self.has: float = info.has
        self.reversed: bool = info.reversed != 0
        self.missing_abilities: int = info.missing_abilities
        self.link: LinkId = LinkId(info.link.index1, info.link.revision)
        self.link_start: Tuple[float, ...] = tuple(info.link_start)
        self.text: str = info.text.decode("utf-8", "replace")

    def __repr__(self) -> str:
        return "PathShortfall(%s, %r)" % (getattr(self.reason, "name", self.reason), self.text)


class PathRequest:
    """A queued path request (World.request_path). wait() blocks for it, ``await request`` (or
    ``await request.wait_async()``) awaits it on an asyncio loop, result() reads it. Its ticket is released
    on leaving ``with world.request_path(...) as request:``, by release(), or when the object is dropped:
    a request released before it finished is cancelled (its on_finished still runs, with PATH_CANCELLED).
    detach() keeps the ticket for the caller to release. It equals its PathTicket (``ticket``) and passes for
    it to World's ticket methods and to raw ``lib`` calls."""

    def __init__(self, world: World, completion: _PathCompletion) -> None:
        self.world = world
        self.ticket = PathTicket()
        self._completion = completion
        self._owned = False  # the ticket is this object's to release

    @property
    def _as_parameter_(self) -> PathTicket:  # what ctypes passes for it
        return self.ticket

    def wait(self, timeout: Optional[float] = None) -> Union[PathOutcome, int]:
        """World.wait_path: the outcome once finished, PATH_PENDING when `timeout` seconds passed first."""
        return self.world.wait_path(self, timeout)

    async def wait_async(self) -> Union[PathOutcome, int]:
        """The outcome, awaited on the running asyncio loop: the request's callback wakes it through
        loop.call_soon_threadsafe (no thread, no polling). In a world without path workers
        (path_worker_count 0) nobody else would plan it, so the await plans the queue itself on the loop's
        thread, as wait() does: one request at a time (nl_path_process), oldest first, letting the loop run
        between requests, until this one has finished (or another thread has taken the rest of the queue).
        Cancelling the awaiting task leaves the request queued: cancel() it."""
        import asyncio  # not at module import: most hosts never await
        loop = asyncio.get_running_loop()
        future = loop.create_future()
        self._completion.add_waiter(loop, future)
        if not future.done() and self.world.path_queue_stats().workers == 0:
            while not future.done():
                if self.world.process_paths(max_requests=1) == 0:
                    break  # the queue is empty: another thread is planning this one, and its callback wakes us
                await asyncio.sleep(0)  # lets the loop run, and settle the future if that was this request
        return await future

    def __await__(self) -> Generator[Any, None, Union[PathOutcome, int]]:
        return self.wait_async().__await__()

    def poll(self) -> Union[PathOutcome, int]:
        return self.world.poll_path(self)

    def result(self) -> Optional[PathResult]:
        """World.path_result: the PathResult, or None while pending."""
        return self.world.path_result(self)

    def cancel(self) -> None:
        self.world.cancel_path(self)

    def release(self) -> None:
        """Releases the ticket (World.release_path) unless it is released or detached already."""
        if self._owned:
            self.world.release_path(self)

    def detach(self) -> PathTicket:
        """The ticket, no longer released by this object: the caller releases it (World.release_path)."""
        self._owned = False
        return self.ticket

    def __enter__(self) -> PathRequest:
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()

    def __del__(self) -> None:
        # The safety net: a request dropped without release. Once its world is closed the ticket is gone
        # with it; at interpreter exit the module may be half torn down.
        world = getattr(self, "world", None)
        if getattr(self, "_owned", False) and world is not None and world._pointer is not None:
            try:
                self.release()
            except Exception:
                pass

    def __eq__(self, other: object) -> bool:
        if isinstance(other, PathRequest):
            return self.ticket == other.ticket
        if isinstance(other, PathTicket):
            return self.ticket == other
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.ticket)

    def __repr__(self) -> str:
        return "PathRequest(%r)" % (self.ticket,)


TicketLike = Union[PathTicket, PathRequest]


# ---------------------------------------------------------------------------------------------------------
# The world
# ---------------------------------------------------------------------------------------------------------


class World:
    """A NavLink world (nl_world*). Use as a context manager, or call close()."""

    # Points fetched in one go by find_path when the path has no more; longer ones are planned again.
    _FIRST_POINT_CAPACITY = 64

    def __init__(self, worker_count: int = WORKERS_AUTO, path_worker_count: int = WORKERS_AUTO,
                 log: Optional[LogHandler] = None, log_level: int = LOG_WARNING,
                 task_enqueue_fn: Optional[Callable[..., Any]] = None, task_finish_fn: Optional[Callable[..., Any]] = None,
                 task_user: Optional[int] = None, agent_paths_per_step: Optional[int] = None) -> None:
        """log: callable(level, status, message), called on the failing thread (maybe a NavLink worker).

        agent_paths_per_step: agents' paths planned in one step() at most (None: the library's default, 32);
        when many agents ask at once, the rest wait their turn (AGENT_WAITING), oldest first.

        task_enqueue_fn, task_finish_fn, task_user: a host task system for the world's batch work
        (navlink.h's nl_task_enqueue_fn and nl_task_finish_fn; worker_count is then the host's workers):
        TaskEnqueueFn / TaskFinishFn objects (native function pointers) or Python callables with their
        arguments, (user, task, task_context, item_count, min_range) -> handle or None, and
        (user, handle). The world keeps them alive until close()."""
        d = lib.nl_default_world_def()
        d.worker_count = worker_count
        d.path_worker_count = path_worker_count
        d.log_level = log_level
        if agent_paths_per_step is not None:
            d.agent_paths_per_step = agent_paths_per_step
        self._tasks = None
        if task_enqueue_fn is not None or task_finish_fn is not None:
            def as_type(fn, fn_type):
                return fn if fn is None or isinstance(fn, fn_type) else fn_type(fn)
            self._tasks = (as_type(task_enqueue_fn, TaskEnqueueFn), as_type(task_finish_fn, TaskFinishFn))
            if self._tasks[0] is not None:
                d.task_enqueue_fn = self._tasks[0]
            if self._tasks[1] is not None:
                d.task_finish_fn = self._tasks[1]
            d.task_user = task_user
        self._log_key = None
        if log is not None:
            self._log_key = _register(log)
            d.log_fn = _log_trampoline
            d.log_user = self._log_key
        pointer = c_void_p()
        status = lib.nl_world_create(byref(d), byref(pointer))
        if failed(status):
            message = last_error_message()
            if self._log_key is not None:
                _lookup(self._log_key, remove=True)
            raise NavLinkError(status, message)
        self._pointer = pointer
        self._plugin_entries = []

    def close(self) -> None:
        """Destroys the world: queued path requests finish as cancelled (their callbacks run now)."""
        if self._pointer is not None:
            lib.nl_world_destroy(self._pointer)
            self._pointer = None
            if self._log_key is not None:
                _lookup(self._log_key, remove=True)

    def __del__(self) -> None:
        # A world dropped without close(): nothing else can be using it any more.
        if getattr(self, "_pointer", None) is not None and lib is not None:
            self.close()

    def __enter__(self) -> World:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def pointer(self) -> c_void_p:
        """The nl_world* for `lib` calls; ValueError once closed."""
        if self._pointer is None:
            raise ValueError("the world is closed")
        return self._pointer

    @property
    def worker_count(self) -> int:
        return lib.nl_world_get_worker_count(self.pointer)

    # --- level geometry ---

    def add_mesh(self, vertices: FloatValues, indices: IndexValues, flags: int = 0,
                 transform: Optional[FloatValues] = None, user_data: int = 0, area: int = 0,
                 metres_per_unit: float = 0.0, up_axis: int = UP_AXIS_NOT_SAID) -> MeshId:
        """Registers a triangle mesh (copied by the library). vertices: x y z numbers, flat or in rows
        ([(x, y, z), ...], a buffer of shape (n, 3), or (n, k > 3) with x y z first in each row: read with
        that stride); indices: three per triangle, flat or in rows of three. Each a list or tuple (of
        numbers, or of rows: lists, tuples, numpy rows), or a buffer: read in place when it holds the C
        type (a numpy float32 array; uint32 or int32), an array.array ('f'; 'I'), a memoryview, or bytes
        holding them), converted once from other numbers (numpy float64, int64, uint16..., array('d'), a
        strided view); integers out of range or floats given as indices are refused (ValueError, TypeError).
        flags: MESH_MOVABLE, MESH_CLOCKWISE (fronts wound clockwise, as Godot's), MESH_OBSTACLE (blocks
        navmesh builds, never walked on) or MESH_NOT_IN_NAVMESH (left out of them), or'd. area: what navmesh
        builds give the polygons over the mesh (0..MESH_MAX_AREA; the Recast builder carries 0..62), priced
        by a path query's area costs; mesh_info(...).area reports it. metres_per_unit: the length of one
        unit of the vertices in metres (0.01 for centimetres, 0.0254 for inches, 1 for metres; 1e-6..1e6);
        0, not said, is read as metres and a navmesh build warns when the level looks otherwise
        (BUILD_WARNING_UNITS). up_axis: UP_AXIS_Z for vertices with z up (Blender's, Unreal's), turned to
        NavLink's y up; UP_AXIS_Y says y up; UP_AXIS_NOT_SAID is read as y up and a build warns when the
        level looks z up (BUILD_WARNING_Z_UP). Both apply to the vertices before the transform, which is in
        metres as every other position and length; mesh_info(...) reports them as given."""
        d, keep = self._mesh_def(flags, transform, user_data, area, metres_per_unit, up_axis)
        v = _c_array("vertices", vertices, c_float, group=3, wider_rows=True)
        i = _c_array("indices", indices, c_uint32, group=3)
        d.vertices, d.vertex_count, d.vertex_stride = _pointer(v, c_float), v.count // v.row, v.row * sizeof(c_float)
        d.indices, d.triangle_count = _pointer(i, c_uint32), i.count // 3
        mesh = MeshId()
        _check(lib.nl_mesh_add(self.pointer, byref(d), byref(mesh)))
        return mesh

    @staticmethod
    def _mesh_def(flags: int, transform: Optional[FloatValues], user_data: int, area: int, metres_per_unit: float,
                  up_axis: int) -> Tuple[MeshDef, Any]:
        d = lib.nl_default_mesh_def()
        t = _floats(transform, "transform", length=16) if transform is not None else None
        d.flags, d.user_data, d.area = flags, user_data, area
        d.metres_per_unit, d.up_axis = metres_per_unit, up_axis
        d.transform = ctypes.cast(t, POINTER(c_float)) if t is not None else None
        return d, t

    def add_obj_file(self, path: Union[str, "os.PathLike[str]"], flags: int = 0,
                     transform: Optional[FloatValues] = None, user_data: int = 0, area: int = 0,
                     metres_per_unit: float = 0.0, up_axis: int = UP_AXIS_NOT_SAID) -> MeshId:
        """An OBJ file as one mesh (flags, area, metres_per_unit and up_axis as add_mesh takes them)."""
        d, keep = self._mesh_def(flags, transform, user_data, area, metres_per_unit, up_axis)
        mesh = MeshId()
        _check(lib.nl_mesh_add_obj_file(self.pointer, os.fsencode(path), byref(d), byref(mesh)))
        return mesh

    def add_obj_memory(self, data: ByteValues, flags: int = 0, transform: Optional[FloatValues] = None,
                       user_data: int = 0, area: int = 0, metres_per_unit: float = 0.0,
                       up_axis: int = UP_AXIS_NOT_SAID) -> MeshId:
        """An OBJ file's text from bytes or any buffer (read in place); flags, area, metres_per_unit and
        up_axis as add_mesh takes them."""
        d, keep = self._mesh_def(flags, transform, user_data, area, metres_per_unit, up_axis)
        text = _c_array("data", data, c_uint8)
        mesh = MeshId()
        _check(lib.nl_mesh_add_obj_memory(self.pointer, ctypes.cast(text.items, c_char_p), text.count, byref(d),
                                          byref(mesh)))
        return mesh

    def remove_mesh(self, mesh: MeshId) -> None:
        """Removes a mesh (STATUS_INVALID_ARGUMENT for a mesh a navmesh rides: remove the navmesh first)."""
        _check(lib.nl_mesh_remove(self.pointer, mesh))

    def set_mesh_transform(self, mesh: MeshId, transform: FloatValues) -> None:
        """Replaces the mesh's transform (16 floats, column-major, affine). The navmeshes that ride it move
        with it; such a mesh takes rotations and translations only (STATUS_INVALID_ARGUMENT otherwise)."""
        _check(lib.nl_mesh_set_transform(self.pointer, mesh, _floats(transform, "transform", length=16)))

    def is_mesh_valid(self, mesh: MeshId) -> bool:
        return lib.nl_mesh_is_valid(self.pointer, mesh) != 0

    def mesh_info(self, mesh: MeshId) -> MeshInfo:
        info = MeshInfo()
        _check(lib.nl_mesh_get_info(self.pointer, mesh, byref(info)))
        return info

    def meshes(self) -> List[MeshId]:
        return _two_call(lambda b, c, n: lib.nl_world_get_meshes(self.pointer, b, c, n), MeshId)

    def cast_rays(self, rays: Sequence[Ray]) -> List[RayHit]:
        """rays: Ray structs; returns one RayHit each."""
        rays = (Ray * len(rays))(*rays)
        hits = _growable_array(RayHit, len(rays))
        _check(lib.nl_world_cast_rays(self.pointer, rays, len(rays), hits))
        return list(hits)

    def segments_blocked(self, segments: Sequence[Tuple[Sequence[float], Sequence[float]]]) -> List[bool]:
        """segments: (from, to) pairs of points; returns a bool each."""
        items = (Segment * len(segments))(*[
            Segment(_point(a, "segments[%d] from" % k), _point(b, "segments[%d] to" % k))
            for k, (a, b) in enumerate(segments)])
        blocked = (c_uint8 * len(segments))()
        _check(lib.nl_world_segments_blocked(self.pointer, items, len(segments), blocked))
        return [b != 0 for b in blocked]

    # --- navmeshes ---

    def build_navmesh(self, agent_type: Optional[AgentType] = None, recast: Optional[RecastSettings] = None,
                      settings_json: Optional[str] = None, builder: Optional[str] = None,
                      carrier: Optional[MeshId] = None, progress: Optional[ProgressHandler] = None) -> NavmeshId:
        """Builds a navmesh with a builder plugin ("recast" when None): from every static mesh, or with
        `carrier` (a MeshId of an MESH_MOVABLE mesh) from that mesh alone, in its own space; the navmesh
        then rides it (navmesh_info(...).carrier). MESH_NOT_IN_NAVMESH meshes are left out, MESH_OBSTACLE
        ones only block, and each mesh's area goes to the polygons over it. Meshes that look wound clockwise
        (turned over, they would hold much more floor for the agent than as given) are named in a logged
        warning with MESH_CLOCKWISE and counted in navmesh_info(...).turned_over_mesh_count. A level that
        looks given in other units than metres, or with z up, where its meshes did not say (add_mesh's
        metres_per_unit and up_axis) is said in a logged warning too; navmesh_info(...).build_warnings has a
        BUILD_WARNING_* bit for each of the three (CLOCKWISE, UNITS, Z_UP). Both are 0 for a navmesh added
        from polygons or loaded from a file, and the build still succeeds. progress: callable(fraction,
        stage) -> bool, called on this thread with fractions from 0 to 1; False cancels the build
        (NavLinkError with STATUS_CANCELLED, nothing added); an exception it raises cancels the build and
        is raised here."""
        d = self._build_def(agent_type, recast, settings_json, builder)
        if carrier is not None:
            d.carrier = carrier
        navmesh = NavmeshId()

        def build(progress_fn: Any, progress_user: Any) -> int:
            d.progress, d.progress_user = progress_fn, progress_user
            return lib.nl_navmesh_build(self.pointer, byref(d), byref(navmesh))
        _with_progress(progress, build)
        return navmesh

    @staticmethod
    def _build_def(agent_type: Optional[AgentType], recast: Optional[RecastSettings], settings_json: Optional[str],
                   builder: Optional[str]) -> NavmeshBuildDef:
        """An nl_navmesh_build_def of these (build_navmesh, build_tiles); it holds what it points to."""
        d = lib.nl_default_navmesh_build_def()
        d.agent_type = agent_type if agent_type is not None else default_agent_type()
        d.builder = builder.encode() if builder is not None else None
        d.settings = ctypes.addressof(recast) if recast is not None else None
        if settings_json is not None:
            data = settings_json.encode()
            d.settings_json, d.settings_json_length = data, len(data)
        return d

    def add_navmesh(self, vertices: FloatValues, indices: IndexValues,
                    polygon_vertex_counts: Optional[ByteValues] = None, areas: Optional[ByteValues] = None,
                    weld_tolerance: Optional[float] = None, agent_type: Optional[AgentType] = None,
                    detail: Optional[Tuple[FloatValues, IndexValues, IndexValues]] = None,
                    carrier: Optional[MeshId] = None, tile: Optional[NavmeshTile] = None) -> NavmeshId:
        """The host's navmesh (copied, repaired). vertices and indices as add_mesh takes them (rows of x y z
        first; indices: each polygon's corners, polygon after polygon); polygon_vertex_counts: corners per
        polygon (bytes), None when every polygon is a triangle; areas: an area id (byte) per polygon or
        None. detail: (vertices, triangles, triangle_starts: polygon count + 1 of them) or None. Lists
        (flat or of rows) or buffers, read in place or converted once as add_mesh reads them. carrier: a
        MeshId of an MESH_MOVABLE mesh the navmesh rides, or None; with one, the coordinates are in that
        mesh's own space and set_mesh_transform moves the navmesh with it. tile: a NavmeshTile to add the
        polygons as that tile of a grid: the navmesh is then tiled, of that one tile, and add_tile grows it."""
        d, keep = self._navmesh_def(vertices, indices, polygon_vertex_counts, areas, weld_tolerance, agent_type,
                                    detail, tile)
        if carrier is not None:
            d.carrier = carrier
        navmesh = NavmeshId()
        _check(lib.nl_navmesh_add(self.pointer, byref(d), byref(navmesh)))
        return navmesh

    @staticmethod
    def _navmesh_def(vertices: FloatValues, indices: IndexValues, polygon_vertex_counts: Optional[ByteValues],
                     areas: Optional[ByteValues], weld_tolerance: Optional[float], agent_type: Optional[AgentType],
                     detail: Optional[Tuple[FloatValues, IndexValues, IndexValues]],
                     tile: Optional[NavmeshTile]) -> Tuple[NavmeshDef, list]:
        """An nl_navmesh_def over the arrays, and the arrays it points into (to keep alive for the call)."""
        d = lib.nl_default_navmesh_def()
        v = _c_array("vertices", vertices, c_float, group=3, wider_rows=True)
        i = _c_array("indices", indices, c_uint32)
        keep = [v, i]
        d.vertices, d.vertex_count, d.vertex_stride = _pointer(v, c_float), v.count // v.row, v.row * sizeof(c_float)
        d.indices = _pointer(i, c_uint32)
        if polygon_vertex_counts is not None:
            counts = _c_array("polygon_vertex_counts", polygon_vertex_counts, c_uint8)
            keep.append(counts)
            # The library reads as many indices as the polygons have corners: more than given must not be read.
            corners = sum(bytes(counts.items))
            if corners != i.count:
                raise ValueError("indices: %d values, but polygon_vertex_counts adds up to %d corners" % (
                    i.count, corners))
            d.polygon_vertex_counts, d.polygon_count = _pointer(counts, c_uint8), counts.count
        else:
            _checked_length("indices", i, 3, None)
            d.polygon_count = i.count // 3
        if areas is not None:
            keep.append(_c_array("areas", areas, c_uint8, length=d.polygon_count))
            d.areas = _pointer(keep[-1], c_uint8)
        if weld_tolerance is not None:
            d.weld_tolerance = weld_tolerance
        if agent_type is not None:
            d.agent_type = agent_type
        if detail is not None:
            dv, dt, ds = (_c_array("detail vertices", detail[0], c_float, group=3),
                          _c_array("detail triangles", detail[1], c_uint32, group=3),
                          _c_array("detail triangle_starts", detail[2], c_uint32, length=d.polygon_count + 1))
            keep += [dv, dt, ds]
            d.detail_vertices, d.detail_vertex_count = _pointer(dv, c_float), dv.count // 3
            d.detail_triangles, d.detail_triangle_count = _pointer(dt, c_uint32), dt.count // 3
            d.detail_triangle_starts = _pointer(ds, c_uint32)
        if tile is not None:
            d.tile_x, d.tile_z, d.tile_width = tile.x, tile.z, tile.width
            d.tile_origin_x, d.tile_origin_z = tile.origin[0], tile.origin[1]
        return d, keep

    def remove_navmesh(self, navmesh: NavmeshId) -> None:
        _check(lib.nl_navmesh_remove(self.pointer, navmesh))

    def is_navmesh_valid(self, navmesh: NavmeshId) -> bool:
        return lib.nl_navmesh_is_valid(self.pointer, navmesh) != 0

    def navmesh_info(self, navmesh: NavmeshId) -> NavmeshInfo:
        info = NavmeshInfo()
        _check(lib.nl_navmesh_get_info(self.pointer, navmesh, byref(info)))
        return info

    def navmesh_vertices(self, navmesh: NavmeshId) -> List[Tuple[float, float, float]]:
        """The vertices after welding, as (x, y, z) tuples."""
        vertices = _two_call(lambda b, c, n: lib.nl_navmesh_get_vertices(
            self.pointer, navmesh, ctypes.cast(b, POINTER(c_float)), c, n), Vec3)
        return [tuple(v) for v in vertices]

    def polygon(self, navmesh: NavmeshId, index: int) -> NavPolygon:
        polygon = NavPolygon()
        _check(lib.nl_navmesh_get_polygon(self.pointer, navmesh, index, byref(polygon)))
        return polygon

    def boundary_edges(self, navmesh: NavmeshId) -> List[BoundaryEdge]:
        return _two_call(lambda b, c, n: lib.nl_navmesh_get_boundary_edges(self.pointer, navmesh, b, c, n), BoundaryEdge)

    # --- tiles of a tiled navmesh (built with RecastSettings.tile_size, or added with a NavmeshTile) ---

    def add_tile(self, navmesh: NavmeshId, tile: NavmeshTile, vertices: FloatValues, indices: IndexValues,
                 polygon_vertex_counts: Optional[ByteValues] = None, areas: Optional[ByteValues] = None,
                 weld_tolerance: Optional[float] = None, agent_type: Optional[AgentType] = None,
                 detail: Optional[Tuple[FloatValues, IndexValues, IndexValues]] = None,
                 carrier: Optional[MeshId] = None) -> None:
        """Adds the host's polygons (as add_navmesh takes them) as the tile `tile` of a tiled navmesh: on its
        grid (tile.width and tile.origin as navmesh_info(navmesh).tile_width and tile_origin), made for its
        agent type, in the space of its carrier (`carrier`: the navmesh's, None for one that rides none), at a
        place no tile holds; the navmesh is joined again with it. NavLinkError with STATUS_INVALID_ARGUMENT
        otherwise (a navmesh that is not tiled, another grid, agent type or carrier, a tile loaded there
        already: remove it first), nothing changed. A tile's file (save_tile) is added with add_tile_bytes or
        add_tile_file."""
        d, keep = self._navmesh_def(vertices, indices, polygon_vertex_counts, areas, weld_tolerance, agent_type,
                                    detail, tile)
        if carrier is not None:
            d.carrier = carrier
        _check(lib.nl_navmesh_add_tile(self.pointer, navmesh, byref(d)))

    def remove_tile(self, navmesh: NavmeshId, tile: TileLike) -> None:
        """Removes the tile at `tile` ((x, z), a TileCoord or a NavmeshTile) from a tiled navmesh. NavLinkError
        with STATUS_NOT_FOUND when no tile is loaded there (removed twice), STATUS_INVALID_ARGUMENT for a navmesh
        that is not tiled or its last tile (remove the navmesh instead); nothing changed."""
        _check(lib.nl_navmesh_remove_tile(self.pointer, navmesh, _tile_coord(tile)))

    def build_tiles(self, navmesh: NavmeshId, box_min: Point, box_max: Point, agent_type: Optional[AgentType] = None,
                    recast: Optional[RecastSettings] = None, settings_json: Optional[str] = None,
                    builder: Optional[str] = None, progress: Optional[ProgressHandler] = None) -> None:
        """Builds again, from the level as it is now, the tiles of a tiled navmesh's grid whose squares overlap
        the box [box_min, box_max] seen from above (y is not read), with a builder plugin ("recast" when None)
        and its settings as build_navmesh takes them: they must make tiles of the navmesh's width (the same
        tile_size and cell_size it was built with), and agent_type (None: the default one) must be the
        navmesh's. In one step a tile loaded there is replaced, one that comes out with no walkable surface is
        removed, the others are added. NavLinkError with STATUS_INVALID_ARGUMENT for a navmesh that is not
        tiled, a box not finite or with min > max (or of more than 2^22 tiles), another agent type, settings
        making another tile width, or no tile left; the builder's failures; STATUS_CANCELLED from progress (as
        build_navmesh's); nothing changed on a failure."""
        d = self._build_def(agent_type, recast, settings_json, builder)
        lo, hi = _point(box_min, "box_min"), _point(box_max, "box_max")

        def build(progress_fn: Any, progress_user: Any) -> int:
            d.progress, d.progress_user = progress_fn, progress_user
            return lib.nl_navmesh_build_tiles(self.pointer, navmesh, byref(d), lo, hi)
        _with_progress(progress, build)

    def tiles(self, navmesh: NavmeshId) -> List[Tuple[int, int]]:
        """The loaded tiles' places as (x, z), in row order (z, then x); [] for a navmesh that is not tiled."""
        return [(t.x, t.z) for t in _two_call(lambda b, c, n: lib.nl_navmesh_get_tiles(self.pointer, navmesh, b, c, n),
                                              TileCoord)]

    def find_nearest(self, navmesh: NavmeshId, points: Union[Sequence[Sequence[float]], FloatValues],
                     half_extents: Point) -> List[NavPoint]:
        """The navmesh point nearest each of `points` ((x, y, z) sequences, or flat x y z values or a buffer
        of them) within the box of half_extents around it."""
        queried = _points("points", points)
        found = (NavPoint * (queried.count // 3))()
        _check(lib.nl_navmesh_find_nearest(self.pointer, navmesh, queried.items, len(found),
                                           _point(half_extents, "half_extents"), found))
        return list(found)

    def navmeshes(self) -> List[NavmeshId]:
        return _two_call(lambda b, c, n: lib.nl_world_get_navmeshes(self.pointer, b, c, n), NavmeshId)

    # --- queries on a navmesh for one body (filter None: QueryFilter(), a default walker) ---

    _FIRST_WALK_CAPACITY = 32  # polygons fetched per walk in one go by the raycasts and move_along_surface

    def can_reach(self, navmesh: NavmeshId, from_polygons: IndexValues, to_polygons: IndexValues,
                  filter: Optional[QueryFilter] = None) -> List[bool]:
        """For each pair (from_polygons[i], to_polygons[i]), whether the filter's body can get from the one
        polygon to the other by walking and by the links it can take, exactly as a path request for it would
        find. Each answer takes constant time (the navmesh's reachability map for the body's class, built on the
        first query). Lists or buffers of 32-bit integers, of one length."""
        sources = _c_array("from_polygons", from_polygons, c_uint32)
        targets = _c_array("to_polygons", to_polygons, c_uint32, length=sources.count)
        query_filter, keep = _filter_def(filter)
        answers = (c_uint8 * sources.count)()
        _check(lib.nl_navmesh_can_reach(self.pointer, navmesh, query_filter, _pointer(sources, c_uint32),
                                        _pointer(targets, c_uint32), sources.count, answers))
        return [a != 0 for a in answers]

    def reachable_polygons(self, navmesh: NavmeshId, from_polygon: int,
                           filter: Optional[QueryFilter] = None) -> List[int]:
        """Every polygon the filter's body can reach from from_polygon (itself included), ascending."""
        query_filter, keep = _filter_def(filter)
        return _two_call(lambda b, c, n: lib.nl_navmesh_get_reachable_polygons(
            self.pointer, navmesh, query_filter, from_polygon, b, c, n), c_uint32)

    def islands(self, navmesh: NavmeshId, filter: Optional[QueryFilter] = None) -> Tuple[List[int], int]:
        """(the island of every polygon, the number of islands) for the filter's body: polygons of one island
        reach each other; one-way links may lead from one island to another (ask can_reach). Islands are
        numbered from 0 in order of their lowest polygon; NO_ISLAND for polygons in excluded areas."""
        query_filter, keep = _filter_def(filter)
        island_count = c_uint32()
        islands = _two_call(lambda b, c, n: lib.nl_navmesh_get_islands(
            self.pointer, navmesh, query_filter, b, c, n, byref(island_count)), c_uint32)
        return islands, island_count.value

    def raycast_batch(self, navmesh: NavmeshId, rays: Sequence[Union[NavmeshRay, Tuple[Point, int, Point]]],
                      filter: Optional[QueryFilter] = None) -> List[NavmeshRaycastHit]:
        """Walks each ray (a NavmeshRay, or a (start, start_polygon, end) tuple) in a straight line (seen from
        above) from its start, over its start_polygon, towards its end along the navmesh surface, as Detour's
        raycast: how far a body walks before a wall (the navmesh's outline, or an area the filter excludes)
        stops it. Returns one hit per ray (its polygon_count counts the polygons crossed). The navmesh is
        looked up once and large batches run over the world's workers; a ray the library refuses (its start
        not over its polygon...) fails the whole batch, naming its index."""
        items = self._navmesh_rays(rays)
        return list(self._raycast_c(navmesh, filter, items, None, 0))

    def raycast_batch_with_polygons(self, navmesh: NavmeshId,
                                    rays: Sequence[Union[NavmeshRay, Tuple[Point, int, Point]]],
                                    filter: Optional[QueryFilter] = None) -> List[Tuple[NavmeshRaycastHit, List[int]]]:
        """raycast_batch with the polygons each ray crossed: (hit, [its start polygon, ..., hit.end_polygon])
        per ray. Room for 32 per ray is asked first; the rays that crossed more are walked again, together,
        with room for the most any of them crossed."""
        items = self._navmesh_rays(rays)
        room = self._FIRST_WALK_CAPACITY
        buffer = (c_uint32 * (len(items) * room))()
        walks = [[hit, []] for hit in self._raycast_c(navmesh, filter, items, buffer, room)]
        longer = []
        for i, walk in enumerate(walks):
            if walk[0].polygon_count > room:
                longer.append(i)
            else:
                walk[1] = list(buffer[i * room:i * room + walk[0].polygon_count])
        while longer:
            # The hits say how many: walk those rays again with room for the most of them.
            again = (NavmeshRay * len(longer))(*[items[i] for i in longer])
            room = max(walks[i][0].polygon_count for i in longer)
            buffer = (c_uint32 * (len(longer) * room))()
            still = []
            for k, hit in enumerate(self._raycast_c(navmesh, filter, again, buffer, room)):
                i = longer[k]
                walks[i][0] = hit
                if hit.polygon_count > room:
                    still.append(i)  # cannot happen on a navmesh that never changes; asked again all the same
                else:
                    walks[i][1] = list(buffer[k * room:k * room + hit.polygon_count])
            longer = still
        return [(hit, polygons) for hit, polygons in walks]

    def raycast(self, navmesh: NavmeshId, start_polygon: int, start: Point, end: Point,
                filter: Optional[QueryFilter] = None) -> Tuple[NavmeshRaycastHit, List[int]]:
        """Walks in a straight line (seen from above) from start, over start_polygon (from find_nearest), towards
        end along the navmesh surface, as Detour's raycast: how far a body walks before a wall (the navmesh's
        outline, or an area the filter excludes) stops it. Returns the hit and the polygons crossed (the start
        polygon first, hit.end_polygon last). A batch of one ray (raycast_batch_with_polygons): room for 32
        polygons, and a second walk with room for hit.polygon_count when it crossed more."""
        return self.raycast_batch_with_polygons(navmesh, [NavmeshRay(start, start_polygon, end)], filter)[0]

    @staticmethod
    def _navmesh_rays(rays: Sequence[Union[NavmeshRay, Tuple[Point, int, Point]]]) -> Any:
        return (NavmeshRay * len(rays))(*[r if isinstance(r, NavmeshRay) else NavmeshRay(*r) for r in rays])

    def _raycast_c(self, navmesh: NavmeshId, filter: Optional[QueryFilter], rays: Any, polygons: Any,
                   per_ray: int) -> Any:
        """nl_navmesh_raycast: the hits (a ctypes array), ray i's first per_ray polygons in polygons[i * per_ray:]."""
        query_filter, keep = _filter_def(filter)
        hits = _growable_array(NavmeshRaycastHit, len(rays))
        _check(lib.nl_navmesh_raycast(self.pointer, navmesh, query_filter, rays, len(rays), hits, polygons, per_ray))
        return hits

    def move_along_surface(self, navmesh: NavmeshId, start_polygon: int, start: Point, target: Point,
                           filter: Optional[QueryFilter] = None) -> Tuple[NavPoint, List[int]]:
        """Slides a point from start (over start_polygon) towards target along the navmesh, as Detour's
        moveAlongSurface: target when the straight way there stays on the navmesh, else the point of the walls
        met nearest to it. Returns that NavPoint (at the surface height, its polygon, found = 1, distance short
        of target) and the polygons visited from the start's to its (room for 32 first; when more were
        visited, the call says how many and is made again with that room)."""
        query_filter, keep = _filter_def(filter)
        origin, goal = _point(start, "start"), _point(target, "target")
        visited = (c_uint32 * self._FIRST_WALK_CAPACITY)()
        while True:
            moved = NavPoint()
            count = c_uint32()
            status = lib.nl_navmesh_move_along_surface(self.pointer, navmesh, query_filter, start_polygon, origin,
                                                       goal, byref(moved), visited, len(visited), byref(count))
            if _buffer_too_small(status) and count.value > len(visited):
                visited = (c_uint32 * count.value)()  # count is how many it visited: slide again with that room
                continue
            _check(status)
            return moved, list(visited[:count.value])

    def random_points(self, navmesh: NavmeshId, count: int, filter: Optional[QueryFilter] = None,
                      centre: Point = (0.0, 0.0, 0.0), radius: float = 0.0, reachable_from: int = NO_POLYGON,
                      seed: int = 1) -> List[NavPoint]:
        """Draws up to `count` points uniformly by surface area over the navmesh polygons allowed: out of the
        filter's excluded areas, within `radius` of `centre` seen from above (radius 0: anywhere), and, unless
        reachable_from is NO_POLYGON, only where the filter's body can reach from that polygon. Returns the
        points drawn (each with its polygon, at the surface height, found = 1, distance 0): `count`, none when
        no allowed polygon lies in the circle, or fewer when the allowed part inside it is too thin. The same
        seed, navmesh and arguments give the same points on every run and thread count."""
        query_filter, keep = _filter_def(filter)
        d = lib.nl_default_random_points_def()
        if query_filter is not None:
            d.filter = ctypes.pointer(keep[0])
        d.centre = Vec3(*_point(centre, "centre"))
        d.radius = radius
        d.reachable_from = reachable_from
        d.seed = seed
        points = (NavPoint * count)()
        found = c_uint32()
        _check(lib.nl_navmesh_random_points(self.pointer, navmesh, byref(d), points, count, byref(found)))
        return list(points[:found.value])

    # --- links ---

    def add_link(self, navmesh: NavmeshId, link_def: LinkDef) -> LinkId:
        """Adds a link (a LinkDef, from default_link_def()) to the navmesh: both ends within 1 m of it, or,
        with link_def.landing_navmesh set (a cross link), the start within 1 m of `navmesh` and the end within
        1 m of the landing navmesh, both in the world as the navmeshes stand now. A cross link is one-way
        (bidirectional: STATUS_INVALID_ARGUMENT) and holds (Link.holds) while its end, seen from its start,
        stays within link_def.tolerance (0.25 m by default) of where it is now."""
        link = LinkId()
        _check(lib.nl_link_add(self.pointer, navmesh, byref(link_def), byref(link)))
        return link

    def update_link(self, link: LinkId, link_def: LinkDef) -> None:
        """Replaces the link's fields with link_def's (errors as add_link)."""
        _check(lib.nl_link_update(self.pointer, link, byref(link_def)))

    def remove_link(self, link: LinkId) -> None:
        _check(lib.nl_link_remove(self.pointer, link))

    def is_link_valid(self, link: LinkId) -> bool:
        return lib.nl_link_is_valid(self.pointer, link) != 0

    def link(self, link: LinkId) -> Link:
        out = Link()
        _check(lib.nl_link_get(self.pointer, link, byref(out)))
        return out

    def links(self, navmesh: NavmeshId) -> List[Link]:
        return _two_call(lambda b, c, n: lib.nl_navmesh_get_links(self.pointer, navmesh, b, c, n), Link)

    def remove_generated_links(self, navmesh: NavmeshId) -> int:
        removed = c_uint32()
        _check(lib.nl_navmesh_remove_generated_links(self.pointer, navmesh, byref(removed)))
        return removed.value

    def generate_links(self, navmesh: NavmeshId, settings: Optional[LinkSettings] = None,
                       plugin_settings_json: Optional[str] = None,
                       progress: Optional[ProgressHandler] = None) -> LinkGenerationReport:
        """Generates the navmesh's links. progress: callable(fraction, stage) -> bool (False cancels); an
        exception it raises cancels the generation and is raised here."""
        s = LinkSettings.from_buffer_copy(settings if settings is not None else default_link_settings())
        if plugin_settings_json is not None:
            data = plugin_settings_json.encode()
            s.plugin_settings_json, s.plugin_settings_json_length = data, len(data)
        report = LinkGenerationReport()
        _with_progress(progress, lambda fn, user: lib.nl_navmesh_generate_links(
            self.pointer, navmesh, byref(s), fn, user, byref(report)))
        return report

    def generate_cross_links(self, first: NavmeshId, second: NavmeshId, tolerance: float,
                             settings: Optional[LinkSettings] = None,
                             progress: Optional[ProgressHandler] = None) -> LinkGenerationReport:
        """Generates the jump and drop links between two navmeshes (a ledge and a platform; either may ride a
        moving mesh) for where they stand now, both ways, as cross links (Link.landing_navmesh) that hold while
        the two stay placed so, within `tolerance` metres (0.25 is a good start). They replace the generated
        cross links between the two that hold now; those made for another placement (a platform's other stop)
        stay, and so do each navmesh's own links. Both navmeshes must be made for the same agent radius and
        height. settings and progress as for generate_links (no plugin kinds run here); the report's jump_links
        and drop_links count the cross links made. STATUS_INVALID_ARGUMENT for the same navmesh twice,
        different bodies, a bad tolerance or setting; STATUS_INVALID_HANDLE for either navmesh stale;
        STATUS_CANCELLED (nothing changed)."""
        s = LinkSettings.from_buffer_copy(settings if settings is not None else default_link_settings())
        report = LinkGenerationReport()
        _with_progress(progress, lambda fn, user: lib.nl_navmesh_generate_cross_links(
            self.pointer, first, second, tolerance, byref(s), fn, user, byref(report)))
        return report

    def update_links_in_box(self, navmesh: NavmeshId, box_min: Point, box_max: Point,
                            progress: Optional[ProgressHandler] = None) -> LinkGenerationReport:
        report = LinkGenerationReport()
        _with_progress(progress, lambda fn, user: lib.nl_navmesh_update_links_in_box(
            self.pointer, navmesh, _point(box_min, "box_min"), _point(box_max, "box_max"), fn, user, byref(report)))
        return report

    def save_links_json(self, navmesh: NavmeshId) -> str:
        """The navmesh's links as JSON (schema "navlink-links" version 1); STATUS_INVALID_ARGUMENT for a
        navmesh with cross links (links files hold the links within one navmesh)."""
        while True:
            length = c_size_t()
            _check(lib.nl_navmesh_save_links_json(self.pointer, navmesh, None, 0, byref(length)))
            buffer = ctypes.create_string_buffer(length.value + 1)
            status = lib.nl_navmesh_save_links_json(self.pointer, navmesh, buffer, len(buffer), byref(length))
            if _buffer_too_small(status):
                continue  # the links changed between the two calls
            _check(status)
            return buffer.raw[:length.value].decode()

    def load_links_json(self, navmesh: NavmeshId, json: str, any_body: bool = False) -> int:
        """Replaces all of the navmesh's links with those in `json`; returns how many were loaded. A file that
        records the body its links were generated for ("made_for") must name the navmesh's (radius and
        height): links for another body are refused (STATUS_INVALID_ARGUMENT, both bodies named) unless
        any_body (LINKS_LOAD_ANY_BODY), which loads them with a warning to the world's log. Files without
        "made_for" load whatever the body. On failure nothing changes."""
        data = json.encode()
        count = c_uint32()
        flags = LINKS_LOAD_ANY_BODY if any_body else 0
        _check(lib.nl_navmesh_load_links_json(self.pointer, navmesh, data, len(data), flags, byref(count)))
        return count.value

    # --- baked navmesh files ---

    def save_navmesh(self, navmesh: NavmeshId) -> bytes:
        """The navmesh, its links (generated and manual, in links() order) and what they were made for, as a
        navmesh file's bytes. STATUS_INVALID_ARGUMENT for a navmesh with cross links (a file holds one
        navmesh's own links)."""
        while True:
            size = c_size_t()
            _check(lib.nl_navmesh_save(self.pointer, navmesh, None, 0, byref(size)))
            buffer = ctypes.create_string_buffer(size.value)
            status = lib.nl_navmesh_save(self.pointer, navmesh, buffer, len(buffer), byref(size))
            if _buffer_too_small(status):
                continue  # the navmesh's links changed between the two calls
            _check(status)
            return buffer.raw[:size.value]

    def save_navmesh_file(self, navmesh: NavmeshId, path: Union[str, "os.PathLike[str]"]) -> None:
        """save_navmesh written to the file at `path`, whole or not at all. STATUS_IO_ERROR: cannot write."""
        _check(lib.nl_navmesh_save_file(self.pointer, navmesh, os.fsencode(path)))

    @staticmethod
    def _load_def(carrier: Optional[MeshId], same_level: bool) -> NavmeshLoadDef:
        d = lib.nl_default_navmesh_load_def()
        if carrier is not None:
            d.carrier = carrier
        d.flags = NAVMESH_LOAD_SAME_LEVEL if same_level else 0
        return d

    def load_navmesh(self, data: ByteValues, carrier: Optional[MeshId] = None, same_level: bool = False) -> NavmeshId:
        """Adds the navmesh and its links held in a navmesh file's bytes (new ids); returns its NavmeshId. A tile's
        file (save_tile) makes a tiled navmesh of that one tile, which add_tile_bytes grows.
        carrier: the MESH_MOVABLE mesh it rides now, for a file whose navmesh rode one
        (NavmeshFileInfo.rides_carrier), else None. same_level: refuse (STATUS_INVALID_ARGUMENT) a file baked
        from other level geometry than the world holds now. STATUS_VERSION_MISMATCH (not a NavLink navmesh
        file, or a newer format), STATUS_PARSE_ERROR (truncated or corrupted); nothing is added on failure."""
        file = _c_array("data", data, c_uint8)
        d = self._load_def(carrier, same_level)
        navmesh = NavmeshId()
        _check(lib.nl_navmesh_load(self.pointer, file.items, file.count, byref(d), byref(navmesh)))
        return navmesh

    def load_navmesh_file(self, path: Union[str, "os.PathLike[str]"], carrier: Optional[MeshId] = None,
                          same_level: bool = False) -> NavmeshId:
        """load_navmesh from the file at `path`; also STATUS_NOT_FOUND (no such file), STATUS_IO_ERROR."""
        d = self._load_def(carrier, same_level)
        navmesh = NavmeshId()
        _check(lib.nl_navmesh_load_file(self.pointer, os.fsencode(path), byref(d), byref(navmesh)))
        return navmesh

    def save_tile(self, navmesh: NavmeshId, tile: TileLike) -> bytes:
        """One tile ((x, z), a TileCoord or a NavmeshTile) of a tiled navmesh as a tile's file's bytes: the tile's
        polygons as built or added, the generated links it owns (those that start on it, wherever they end), what
        it was made for, and its content hash (tile_hash); host links are not in it (save_navmesh saves a whole
        navmesh with them). Load the first tile of a world with load_navmesh (a tiled navmesh of that tile) and
        the others with add_tile_bytes, in any order: the navmesh and links are those the tiles were saved from.
        NavLinkError with STATUS_NOT_FOUND when no tile is loaded there, STATUS_INVALID_ARGUMENT for a navmesh
        that is not tiled or rides a movable mesh (save it whole)."""
        coord = _tile_coord(tile)
        while True:
            size = c_size_t()
            _check(lib.nl_navmesh_save_tile(self.pointer, navmesh, coord, None, 0, byref(size)))
            buffer = ctypes.create_string_buffer(size.value)
            status = lib.nl_navmesh_save_tile(self.pointer, navmesh, coord, buffer, len(buffer), byref(size))
            if _buffer_too_small(status):
                continue  # the tile or its links changed between the two calls
            _check(status)
            return buffer.raw[:size.value]

    def save_tile_file(self, navmesh: NavmeshId, tile: TileLike, path: Union[str, "os.PathLike[str]"]) -> None:
        """save_tile written to the file at `path`, whole or not at all. STATUS_IO_ERROR: cannot write."""
        _check(lib.nl_navmesh_save_tile_file(self.pointer, navmesh, _tile_coord(tile), os.fsencode(path)))

    def add_tile_bytes(self, navmesh: NavmeshId, data: ByteValues) -> None:
        """Adds the tile a tile's file's bytes (any buffer; save_tile) hold to a tiled navmesh, with its links, as
        add_tile adds a tile; no link is generated: a link to a tile not loaded waits, out of every path, until
        that tile is added. STATUS_VERSION_MISMATCH (not a NavLink navmesh file, or a newer format),
        STATUS_PARSE_ERROR (truncated or corrupted), STATUS_INVALID_ARGUMENT (a whole navmesh's file; a tile of
        another grid or agent type, or made with another builder, builder settings or link settings than the
        navmesh; a tile already loaded there; polygons or links that do not fit); nothing changed on failure."""
        file = _c_array("data", data, c_uint8)
        _check(lib.nl_navmesh_add_tile_bytes(self.pointer, navmesh, file.items, file.count))

    def add_tile_file(self, navmesh: NavmeshId, path: Union[str, "os.PathLike[str]"]) -> None:
        """add_tile_bytes from the file at `path`; also STATUS_NOT_FOUND (no such file), STATUS_IO_ERROR."""
        _check(lib.nl_navmesh_add_tile_file(self.pointer, navmesh, os.fsencode(path)))

    def tile_hash(self, navmesh: NavmeshId, tile: TileLike) -> int:
        """The content hash of the tile at `tile` of a tiled navmesh's grid (loaded or not), from what the world
        holds now: the level's triangles in the columns the tile, its links and its neighbours' borders reach,
        the builder and its settings, the link settings and the body. A tile's file records the hash it was saved
        with (NavmeshFileInfo.content_hash): a bake skips a tile whose hash it holds. Never 0.
        STATUS_INVALID_ARGUMENT for a navmesh that is not tiled."""
        value = c_uint64()
        _check(lib.nl_navmesh_get_tile_hash(self.pointer, navmesh, _tile_coord(tile), byref(value)))
        return value.value

    # --- paths ---

    def find_path(self, query: PathQuery) -> PathResult:
        """Plans a path now on this thread (for tools and tests; games queue requests)."""
        d, keep = query._def()
        points = _growable_array(PathPoint, self._FIRST_POINT_CAPACITY)
        while True:
            info = PathResultInfo()
            count = c_uint32()
            status = lib.nl_path_find(self.pointer, byref(d), byref(info), points, len(points), byref(count))
            if _buffer_too_small(status):
                # More points than room: this thread kept the plan, the second call copies it.
                points = _growable_array(PathPoint, count.value)
                continue
            _check(status)
            return PathResult(info, list(points[:count.value]))

    def explain_path(self, query: PathQuery) -> PathShortfall:
        """Why the query's path falls short of its goal (nl_path_explain): plans it as find_path does and, for a
        PATH_PARTIAL or PATH_NO_PATH outcome, plans again with one limit lifted at a time (the body's width,
        the excluded areas, the links the body cannot take) and names the first that gets there; reason
        PATH_SHORTFALL_NONE when the path reaches the goal or an end is off the navmesh. Up to five searches
        on this thread: for tools, logs and debugging."""
        d, keep = query._def()
        info = PathShortfallInfo()
        _check(lib.nl_path_explain(self.pointer, byref(d), byref(info)))
        return PathShortfall(info)

    def request_path(self, query: PathQuery, on_finished: Optional[PathHandler] = None) -> PathRequest:
        """Queues a request and returns its PathRequest: wait for it, await it, read its result, and release
        its ticket with ``with`` (or release(); dropping it releases it too, cancelling it if pending).
        on_finished(ticket, outcome) runs once when it finishes, on a NavLink path worker, in process_paths,
        in a wait without path workers, in cancel_path, in a release of a pending request or in close(); it
        may run before this returns."""
        d, keep = query._def()
        completion = _PathCompletion(on_finished)
        key = _register(completion)
        d.callback, d.user = _path_trampoline, key
        request = PathRequest(self, completion)
        status = lib.nl_path_request(self.pointer, byref(d), byref(request.ticket))
        if failed(status):
            message = last_error_message()
            _lookup(key, remove=True)  # a refused request never calls back
            raise NavLinkError(status, message)
        request._owned = True
        return request

    def poll_path(self, ticket: TicketLike) -> Union[PathOutcome, int]:
        outcome = c_uint32()
        _check(lib.nl_path_poll(self.pointer, ticket, byref(outcome)))
        return _outcome(outcome.value)

    # A blocking wait returns to Python this often, so that Ctrl-C (a signal handler) can stop a long one.
    _WAIT_SLICE_SECONDS = 0.25

    def wait_path(self, ticket: TicketLike, timeout: Optional[float] = None) -> Union[PathOutcome, int]:
        """Blocks until the request has finished or `timeout` seconds have passed (None or inf: as long as it
        takes; 0 only looks) and returns its outcome: PATH_PENDING on a timeout. Other threads run meanwhile
        (the GIL is released). With path_worker_count 0 this thread plans queued requests itself, oldest
        first, their callbacks on it, until this one has finished: a request is never split, so a wait can
        overrun its timeout by the one being planned. NavLinkError: STATUS_INVALID_HANDLE (released ticket),
        STATUS_INVALID_ARGUMENT (called from a path callback)."""
        if timeout is not None and not timeout >= 0:
            raise ValueError("timeout: seconds >= 0, or None to wait as long as it takes; not %r" % (timeout,))
        deadline = None if timeout is None or math.isinf(timeout) else time.monotonic() + timeout
        outcome = c_uint32()
        while True:
            left = self._WAIT_SLICE_SECONDS if deadline is None else max(0.0, deadline - time.monotonic())
            milliseconds = math.ceil(min(left, self._WAIT_SLICE_SECONDS) * 1000)
            status = _check(lib.nl_path_wait(self.pointer, ticket, milliseconds, byref(outcome)))
            if not status & STATUS_IN_PROGRESS or (deadline is not None and time.monotonic() >= deadline):
                return _outcome(outcome.value)

    def path_result(self, ticket: TicketLike) -> Optional[PathResult]:
        """The finished request's PathResult, or None while it is pending."""
        while True:
            info = PathResultInfo()
            count = c_uint32()
            status = lib.nl_path_get_result(self.pointer, ticket, byref(info), None, 0, byref(count))
            if status & STATUS_IN_PROGRESS:
                return None
            if not _buffer_too_small(status):
                _check(status)
            points = _growable_array(PathPoint, count.value)
            status = lib.nl_path_get_result(self.pointer, ticket, byref(info), points, count.value, byref(count))
            if _buffer_too_small(status):
                continue
            _check(status)
            return PathResult(info, list(points[:count.value]))

    def cancel_path(self, ticket: TicketLike) -> None:
        _check(lib.nl_path_cancel(self.pointer, ticket))

    def release_path(self, ticket: TicketLike) -> None:
        """Frees the request's result; the ticket is invalid from now on (a pending request is cancelled,
        its callback still runs once)."""
        _check(lib.nl_path_release(self.pointer, ticket))
        if isinstance(ticket, PathRequest):
            ticket._owned = False

    def process_paths(self, max_requests: int = 0, max_milliseconds: float = 0.0, max_search_nodes: int = 0,
                      budget: Optional[PathBudget] = None) -> int:
        """Plans queued requests on this thread until the queue is empty or a limit is reached (each 0, or
        max_milliseconds <= 0: no limit; max_search_nodes bounds the polygons the searches visit in all);
        returns how many finished here. `budget` (a PathBudget) replaces the three. How a world with
        path_worker_count 0 runs its queue, e.g. ``world.process_paths(max_milliseconds=2)`` each frame."""
        if budget is None:
            budget = default_path_budget()
            budget.max_requests, budget.max_milliseconds, budget.max_search_nodes = (
                max_requests, max_milliseconds, max_search_nodes)
        processed = c_uint32()
        _check(lib.nl_path_process(self.pointer, byref(budget), byref(processed)))
        return processed.value

    _FINISHED_CHUNK = 16

    def take_finished_paths(self) -> List[FinishedPath]:
        """The requests that finished since the last call, oldest first, each reported once, as
        FinishedPath(ticket, outcome): the way to learn of finished requests on your own thread without a
        callback (callbacks still run too). Requests whose ticket was released are not reported."""
        taken = []
        buffer = _growable_array(PathFinished, self._FINISHED_CHUNK)
        while True:
            count, remaining = c_uint32(), c_uint32()
            _check(lib.nl_path_take_finished(self.pointer, buffer, len(buffer), byref(count), byref(remaining)))
            taken += [FinishedPath(PathTicket(f.ticket.index1, f.ticket.revision), _outcome(f.outcome))
                      for f in buffer[:count.value]]
            if remaining.value == 0:
                return taken
            if remaining.value > len(buffer):
                buffer = _growable_array(PathFinished, remaining.value)

    def path_queue_stats(self) -> PathQueueStats:
        stats = PathQueueStats()
        _check(lib.nl_path_get_queue_stats(self.pointer, byref(stats)))
        return stats

    # --- agents ---

    def add_agent(self, agent_def: AgentDef) -> AgentId:
        """Adds an agent standing still (AGENT_IDLE) at the navmesh point of agent_def.position (NavLinkError
        with STATUS_NOT_FOUND when it is off the navmesh)."""
        agent = AgentId()
        _check(lib.nl_agent_add(self.pointer, byref(agent_def), byref(agent)))
        return agent

    def remove_agent(self, agent: AgentId) -> None:
        _check(lib.nl_agent_remove(self.pointer, agent))

    def is_agent_valid(self, agent: AgentId) -> bool:
        return lib.nl_agent_is_valid(self.pointer, agent) != 0

    def set_agent_destination(self, agent: AgentId, destination: Point) -> None:
        """Sends the agent to the navmesh point of destination, on its navmesh or else on a navmesh that
        cross links join to it (a platform, a ledge across a chasm); STATUS_NOT_FOUND on none of them (the
        destination is not kept). One on a navmesh that rides a moving mesh moves with the mesh. Its path
        is planned in a coming step()."""
        _check(lib.nl_agent_set_destination(self.pointer, agent, _point(destination, "destination")))

    def stop_agent(self, agent: AgentId) -> None:
        """Forgets the destination: the agent stands (AGENT_IDLE); one in the air lands first."""
        _check(lib.nl_agent_stop(self.pointer, agent))

    def teleport_agent(self, agent: AgentId, position: Point) -> None:
        """Puts the agent at the navmesh point of position, keeping its destination (refused while it is
        taking a link)."""
        _check(lib.nl_agent_teleport(self.pointer, agent, _point(position, "position")))

    def set_agent_capabilities(self, agent: AgentId, capabilities: AgentCapabilities) -> None:
        """Changes what the agent's body can do (an AgentCapabilities); it plans again."""
        _check(lib.nl_agent_set_capabilities(self.pointer, agent, byref(capabilities)))

    def set_agent_speed(self, agent: AgentId, max_speed: float, max_acceleration: float) -> None:
        _check(lib.nl_agent_set_speed(self.pointer, agent, max_speed, max_acceleration))

    def step(self, dt: float) -> None:
        """Advances every agent by dt seconds (finite, >= 0) on the world's workers, with the same result
        whatever their number. An agent's trouble is its AGENT_FAILED state and event, not an exception."""
        _check(lib.nl_world_step(self.pointer, dt))

    def agent_info(self, agent: AgentId) -> AgentInfo:
        info = AgentInfo()
        _check(lib.nl_agent_get_info(self.pointer, agent, byref(info)))
        return info

    def agents(self) -> List[AgentInfo]:
        """Every agent's AgentInfo, in a stable order until an agent is removed."""
        return _two_call(lambda b, c, n: lib.nl_world_get_agents(self.pointer, b, c, n), AgentInfo)

    def agent_corners(self, agent: AgentId) -> List[PathPoint]:
        """The PathPoints the agent has yet to reach, the next first: where it walks, and at which point
        it takes which link (segment, link). A route that leaves its navmesh ends at the take-off of the
        cross link, with that link."""
        return _two_call(lambda b, c, n: lib.nl_agent_get_corners(self.pointer, agent, b, c, n), PathPoint)

    def agent_trajectory(self, agent: AgentId) -> Optional[AgentTrajectory]:
        """The AgentTrajectory of the link the agent is taking now, or None while it is on the ground (the
        library's kind TRAJECTORY_NONE), also while it waits at a take-off. In the world: a link within a
        navmesh that rides a moving mesh is given where the mesh is now; a cross link is flown in the world,
        to where its landing was expected to be at landing time."""
        trajectory = AgentTrajectory()
        _check(lib.nl_agent_get_trajectory(self.pointer, agent, byref(trajectory)))
        return None if trajectory.kind == TRAJECTORY_NONE else trajectory

    def agent_events(self) -> List[AgentEvent]:
        """The AgentEvents of the last step(), in agent order. They stay until the next step: read them
        once per step."""
        return _two_call(lambda b, c, n: lib.nl_world_get_agent_events(self.pointer, b, c, n), AgentEvent)

    # --- plugins ---

    def load_plugin(self, path: Union[str, "os.PathLike[str]"]) -> PluginId:
        plugin = PluginId()
        _check(lib.nl_plugin_load(self.pointer, os.fsencode(path), byref(plugin)))
        return plugin

    def register_plugin(self, entry: Any) -> PluginId:
        """entry: a PluginEntryFn; kept alive with everything it hands over for as long as the world."""
        self._plugin_entries.append(entry)
        plugin = PluginId()
        _check(lib.nl_plugin_register(self.pointer, entry, byref(plugin)))
        return plugin

    def plugin_description(self, plugin: PluginId) -> dict:
        """A dict of the description's fields (strings copied)."""
        d = PluginDescription()
        _check(lib.nl_plugin_get_description(self.pointer, plugin, byref(d)))
        return {"name": d.name.decode(), "version": d.version.decode(), "description": d.description.decode(),
                "kinds": d.kinds, "builtin": d.builtin != 0, "abi_version": d.abi_version}

    def plugins(self) -> List[PluginId]:
        return _two_call(lambda b, c, n: lib.nl_world_get_plugins(self.pointer, b, c, n), PluginId)
