# SPDX-License-Identifier: BSD-3-Clause
"""Python binding of surfadapt: ctypes over the C interface (include/surfadapt.h, ABI 1).

Pure Python with numpy; nothing to compile. The header is the contract: every method
here calls the C function of the same name and says which in its docstring.

    import surfadapt
    xyz, tris = surfadapt.icosphere(3, radius=0.5)
    with surfadapt.Surface(xyz, tris) as s:
        s.adapt()
        xyz, tris = s.mesh()
        print(s.measure("volume"))

Arrays go in as anything numpy can convert ((n, 3) coordinates, (m, 3) triangles, ...)
and come out as fresh numpy arrays, never views of the library's memory. A failed call
raises a SurfadaptError subclass carrying the status and sfa_last_error()'s message; as
in C, the surface is then exactly as it was before the call.

The shared library is found, in this order: the `path` given to load_library(); the
environment variable SURFADAPT_LIBRARY; `lib/libsurfadapt.so.1` of the tree this file
lies in (PREFIX/share/surfadapt/python/surfadapt.py once installed, or
bindings/python/surfadapt.py in the source tree); the system's search
(ctypes.util.find_library, then "libsurfadapt.so.1" as the dynamic loader finds it).
"""

import ctypes
import ctypes.util
import enum
import os

import numpy as np

__all__ = [
    "Status", "Param", "Measure", "Surface", "SurfadaptError", "ArgumentError", "MeshError",
    "StateError", "NumericError", "OutOfMemoryError", "InternalError", "load_library",
    "version", "version_number", "abi_version", "status_string", "param_bounds", "icosphere",
]

# The ABI this module is written against; a library of another ABI is refused at load.
ABI_VERSION = 1

# ----------------------------------------------------------------------- constants
# Written out, not parsed from the header at import (the installed module must work
# without the header); tests/python/test_binding.py checks every value against
# include/surfadapt.h, so that they cannot drift.

SFA_VERSION_MAJOR = 1
SFA_VERSION_MINOR = 1
SFA_VERSION_PATCH = 0
SFA_ABI_VERSION = 1


class Status(enum.IntEnum):
    """enum sfa_status."""
    OK = 0
    ERR_ARGUMENT = 1
    ERR_MESH = 2
    ERR_STATE = 3
    ERR_NUMERIC = 4
    ERR_MEMORY = 5
    ERR_INTERNAL = 6


class Param(enum.IntEnum):
    """enum sfa_param: keys of Surface.set_param(); units, ranges and defaults are in the header."""
    EDGE_LENGTH = 0
    ANISOTROPIC = 1
    RIDGE_ANGLE = 2
    CORNER_ANGLE = 3
    METRIC_MIN_ANGLE = 4
    METRIC_MAX_ANGLE = 5
    SPLIT_LENGTH_RATIO = 6
    SPLIT_SHORTEST_RATIO = 7
    CONTRACT_LENGTH_RATIO = 8
    CONTRACT_SHORT_RATIO = 9
    CONTRACT_SMALL_RATIO = 10
    SMALL_ANGLE = 11
    LARGE_ANGLE = 12
    FOLD_SAFETY = 13
    DROP_UNREFERENCED = 14
    RIDGE_TURN_ANGLE = 15
    FLIP_DIHEDRAL_ANGLE = 16
    THREADS = 17
    DENOISE = 18
    ADAPT_PASSES = 19
    CROSSING_GUARD = 20
    VOLUME_CORRECTION = 21
    SIZE_GRADATION = 22
    SHORT_EDGE_RATIO = 23
    COLLISION_SAFE_MOTION = 24
    TOPOLOGY_CHANGE = 25
    MERGE_DISTANCE = 26
    THIN_SHEET_EDGE_RATIO = 27


class Measure(enum.IntEnum):
    """enum sfa_measure_quantity: quantities of Surface.measure()."""
    VOLUME = 0
    AREA = 1
    MIN_ANGLE = 2
    MAX_ANGLE = 3
    MEAN_EDGE_LENGTH = 4
    MAX_ASPECT_RATIO = 5
    MIN_EDGE_LENGTH = 6
    MAX_EDGE_LENGTH = 7
    MAX_NORMAL_TURN = 8
    SECONDS_ANALYSIS = 9
    SECONDS_SMOOTHING = 10
    SECONDS_FLIPPING = 11
    SECONDS_REPAIR = 12
    SELF_INTERSECTIONS = 13
    VOLUME_CORRECTION = 14
    MERGES = 15
    PINCHES = 16
    TOPOLOGY_VOLUME_CHANGE = 17
    DROPS_REMOVED = 18
    VOLUME_LEFT = 19
    UNRESOLVED_AREA = 20
    MIN_ANGLE_RESOLVED = 21


# The header's names as well (SFA_OK, SFA_PARAM_EDGE_LENGTH, SFA_MEASURE_VOLUME, ...), so
# that code ported from C or Fortran reads the same. They are the enum members above.
for _prefix, _enum in (("SFA_", Status), ("SFA_PARAM_", Param), ("SFA_MEASURE_", Measure)):
    for _member in _enum:
        globals()[_prefix + _member.name] = _member
        __all__.append(_prefix + _member.name)
del _prefix, _enum, _member


# -------------------------------------------------------------------------- errors

class SurfadaptError(Exception):
    """A call failed. `status` is the sfa_status code, `message` the library's own text
    (sfa_last_error(), which names the offending element), `function` the C function."""

    def __init__(self, status, message, function=""):
        try:
            self.status = Status(status)
        except ValueError:  # a code this module does not know: keep the number
            self.status = status
        self.message = message
        self.function = function
        super().__init__(status, message)

    def __str__(self):
        return self.message


class ArgumentError(SurfadaptError, ValueError):
    """SFA_ERR_ARGUMENT: a bad argument (unknown key, value out of range, wrong count)."""


class MeshError(SurfadaptError, ValueError):
    """SFA_ERR_MESH: the mesh given is not acceptable; the message names the element."""


class StateError(SurfadaptError):
    """SFA_ERR_STATE: a call out of order, e.g. no mesh set yet."""


class NumericError(SurfadaptError, ArithmeticError):
    """SFA_ERR_NUMERIC: a non-finite value, or a step that cannot be taken without folding."""


class OutOfMemoryError(SurfadaptError, MemoryError):
    """SFA_ERR_MEMORY: an allocation in the library failed."""


class InternalError(SurfadaptError):
    """SFA_ERR_INTERNAL: a bug in the library (please report it); the surface is unchanged."""


_ERROR_CLASSES = {
    Status.ERR_ARGUMENT: ArgumentError,
    Status.ERR_MESH: MeshError,
    Status.ERR_STATE: StateError,
    Status.ERR_NUMERIC: NumericError,
    Status.ERR_MEMORY: OutOfMemoryError,
    Status.ERR_INTERNAL: InternalError,
}

# ------------------------------------------------------------------------- library

_double_p = ctypes.POINTER(ctypes.c_double)
_int32_p = ctypes.POINTER(ctypes.c_int32)
_handle = ctypes.c_void_p
_i32 = ctypes.c_int32
_int = ctypes.c_int
_dbl = ctypes.c_double

# typedef void (*sfa_velocity_fn)(void *ctx, int32_t n, const double *xyz, double t, double *vel);
VELOCITY_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _i32, _double_p, _dbl, _double_p)

# name: (restype, argtypes). Every function of the header except sfa_get_api (the table
# is for C plugin hosts; ctypes resolves the symbols directly) and the unchecked
# sfa_set_velocities, sfa_add_field, sfa_add_face_field and sfa_set_size_field: their
# _checked variants do the same and refuse an array made for another count instead of
# reading past its end.
_PROTOTYPES = {
    "sfa_version_string": (ctypes.c_char_p, []),
    "sfa_abi_version": (_int, []),
    "sfa_version_number": (_int, []),
    "sfa_status_string": (ctypes.c_char_p, [_int]),
    "sfa_create": (_int, [ctypes.POINTER(_handle)]),
    "sfa_destroy": (None, [_handle]),
    "sfa_last_error": (ctypes.c_char_p, [_handle]),
    "sfa_set_mesh": (_int, [_handle, _i32, _double_p, _i32, _int32_p, _i32]),
    "sfa_get_counts": (_int, [_handle, _int32_p, _int32_p]),
    "sfa_get_mesh": (_int, [_handle, _i32, _double_p, _i32, _int32_p, _i32]),
    "sfa_set_param": (_int, [_handle, _int, _dbl]),
    "sfa_get_param": (_int, [_handle, _int, _double_p]),
    "sfa_get_param_bounds": (_int, [_int, _double_p, _double_p]),
    "sfa_set_velocities_checked": (_int, [_handle, _i32, _double_p]),
    "sfa_move": (_int, [_handle, _dbl, _double_p]),
    "sfa_advect": (_int, [_handle, VELOCITY_FN, ctypes.c_void_p, _dbl, _dbl, _double_p]),
    "sfa_smooth": (_int, [_handle, _i32]),
    "sfa_adapt": (_int, [_handle]),
    "sfa_get_feature_ranks": (_int, [_handle, _i32, _int32_p]),
    "sfa_get_vertex_frames": (_int, [_handle, _i32, _double_p, _double_p, _double_p]),
    "sfa_get_ridge_edges": (_int, [_handle, _i32, _int32_p, _int32_p, _i32]),
    "sfa_measure": (_int, [_handle, _int, _double_p]),
    "sfa_set_size_field_checked": (_int, [_handle, _i32, _double_p]),
    "sfa_set_fixed_vertices": (_int, [_handle, _i32, _int32_p, _i32]),
    "sfa_set_required_edges": (_int, [_handle, _i32, _int32_p, _i32]),
    "sfa_add_face_field_checked": (_int, [_handle, _i32, _i32, _double_p, _int32_p]),
    "sfa_get_face_field": (_int, [_handle, _i32, _i32, _double_p]),
    "sfa_get_vertex_origins": (_int, [_handle, _i32, _int32_p, _double_p, _i32]),
    "sfa_get_component_count": (_int, [_handle, _int32_p]),
    "sfa_get_components": (_int, [_handle, _i32, _int32_p]),
    "sfa_measure_component": (_int, [_handle, _i32, _int, _double_p]),
    "sfa_add_field_checked": (_int, [_handle, _i32, _i32, _double_p, _int32_p]),
    "sfa_get_field": (_int, [_handle, _i32, _i32, _double_p]),
    "sfa_set_field": (_int, [_handle, _i32, _i32, _double_p]),
    "sfa_set_face_field": (_int, [_handle, _i32, _i32, _double_p]),
}


class Library:
    """The loaded shared library: `path` as loaded, `lib` the ctypes handle with every
    prototype declared (so a wrong argument type fails in Python, not in C)."""

    def __init__(self, path):
        self.path = path
        try:
            self.lib = ctypes.CDLL(path)
        except OSError as e:
            raise OSError(f"surfadapt: cannot load the shared library {path!r}: {e}") from e
        # The ABI first: a library of another ABI may lack functions, or have other ones.
        try:
            abi_version = self.lib.sfa_abi_version
        except AttributeError as e:
            raise OSError(f"surfadapt: {path!r} has no function sfa_abi_version: not surfadapt") from e
        abi_version.restype, abi_version.argtypes = _int, []
        abi = abi_version()
        if abi != ABI_VERSION:
            raise OSError(f"surfadapt: {path!r} has ABI version {abi}; this module is written for ABI {ABI_VERSION}")
        for name, (restype, argtypes) in _PROTOTYPES.items():
            try:
                function = getattr(self.lib, name)
            except AttributeError as e:
                raise OSError(f"surfadapt: {path!r} has no function {name}: not surfadapt, or too old "
                              f"(this module needs version {SFA_VERSION_MAJOR}.{SFA_VERSION_MINOR} or later)") from e
            function.restype = restype
            function.argtypes = argtypes


_loaded = None


def _candidates():
    env = os.environ.get("SURFADAPT_LIBRARY")
    if env:
        # Set means meant: no quiet fallback to another library when it is wrong.
        return [env], True
    here = os.path.dirname(os.path.abspath(__file__))
    paths = [
        # Installed: PREFIX/share/surfadapt/python/surfadapt.py, library in PREFIX/lib.
        os.path.join(here, os.pardir, os.pardir, os.pardir, "lib", "libsurfadapt.so.1"),
        # Source tree: bindings/python/surfadapt.py, library built into lib/.
        os.path.join(here, os.pardir, os.pardir, "lib", "libsurfadapt.so.1"),
    ]
    found = [os.path.normpath(p) for p in paths if os.path.isfile(p)]
    system = ctypes.util.find_library("surfadapt")
    return found + [system or "libsurfadapt.so.1"], False


def load_library(path=None):
    """Loads the shared library once and returns it (a Library); later calls return the
    same one. `path` (or SURFADAPT_LIBRARY) names the file; see the module's docstring
    for the search otherwise. Raises OSError, naming what was tried, if none loads."""
    global _loaded
    if _loaded is not None:
        if path is not None and os.path.realpath(path) != os.path.realpath(_loaded.path):
            raise OSError(f"surfadapt: {_loaded.path!r} is loaded already; cannot load {path!r} as well")
        return _loaded
    if path is not None:
        _loaded = Library(path)
        return _loaded
    candidates, explicit = _candidates()
    errors = []
    for candidate in candidates:
        try:
            _loaded = Library(candidate)
            return _loaded
        except OSError as e:
            if explicit:
                raise OSError(f"{e} (from SURFADAPT_LIBRARY)") from e
            errors.append(str(e))
    raise OSError("surfadapt: no shared library found; set SURFADAPT_LIBRARY to libsurfadapt.so.1's path. Tried:\n  "
                  + "\n  ".join(errors))


def _text(raw):
    return raw.decode("utf-8", "replace") if raw else ""


def version():
    """sfa_version_string(): the library's version, "MAJOR.MINOR.PATCH"."""
    return _text(load_library().lib.sfa_version_string())


def version_number():
    """sfa_version_number(): MAJOR * 10000 + MINOR * 100 + PATCH."""
    return load_library().lib.sfa_version_number()


def abi_version():
    """sfa_abi_version() of the library loaded."""
    return load_library().lib.sfa_abi_version()


def status_string(status):
    """sfa_status_string(): a description of a status code."""
    return _text(load_library().lib.sfa_status_string(int(status)))


def _key(enum_type, key, what):
    """A key given as the enum member, its number or its name ("edge_length",
    "EDGE_LENGTH", "SFA_PARAM_EDGE_LENGTH") as the int the C call takes."""
    if isinstance(key, str):
        name = key.upper()
        for prefix in ("SFA_PARAM_", "SFA_MEASURE_"):
            if name.startswith(prefix):
                name = name[len(prefix):]
        try:
            return int(enum_type[name])
        except KeyError:
            raise ValueError(f"unknown {what} {key!r}; one of: "
                             + ", ".join(m.name.lower() for m in enum_type)) from None
    if isinstance(key, (bool, float)) or not isinstance(key, (int, np.integer)):
        raise TypeError(f"a {what} is a {enum_type.__name__} member, its number or its name, not {key!r}")
    # An unknown number goes to the library, which refuses it with its own message.
    return int(key)


def param_bounds(key):
    """sfa_get_param_bounds(): (lowest, highest) of the values set_param() accepts for a
    key (an end the header writes in parentheses is itself refused; an unbounded end is inf)."""
    lib = load_library().lib
    lo, hi = _dbl(), _dbl()
    rc = lib.sfa_get_param_bounds(_key(Param, key, "parameter"), ctypes.byref(lo), ctypes.byref(hi))
    if rc != Status.OK:
        # No surface, so no sfa_last_error() message: the status and the key say it all.
        raise _ERROR_CLASSES.get(rc, SurfadaptError)(
            rc, f"sfa_get_param_bounds: {status_string(rc)} (key {key!r})", "sfa_get_param_bounds")
    return lo.value, hi.value


# -------------------------------------------------------------------------- arrays

_INT32_MIN, _INT32_MAX = np.iinfo(np.int32).min, np.iinfo(np.int32).max


def _count(n, what):
    if n > _INT32_MAX:
        raise ValueError(f"{what}: {n} is more than the library's counts (int32) hold")
    return n


def _doubles(values, name, columns=None, rows=None):
    """`values` as a C-contiguous float64 array of shape (rows, columns); `columns` None
    accepts (rows,) or (rows, k). A copy whenever the input is not that already."""
    a = np.asarray(values)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name} must hold real numbers, got an array of {a.dtype}")
    a = np.ascontiguousarray(a, dtype=np.float64)
    if columns is None:
        if a.ndim not in (1, 2) or (a.ndim == 2 and a.shape[1] < 1):
            raise ValueError(f"{name} must have shape (n,) or (n, k) with k >= 1, got {a.shape}")
    elif a.ndim != 2 or a.shape[1] != columns:
        raise ValueError(f"{name} must have shape (n, {columns}), got {a.shape}")
    if rows is not None and a.shape[0] != rows:
        raise ValueError(f"{name} has {a.shape[0]} rows; the mesh has {rows}")
    _count(a.size, name)
    return a


def _indices(values, name, columns):
    """`values` as a C-contiguous int32 array of shape (k, columns), refusing what the
    cast would change: fractions, and numbers outside int32."""
    a = np.asarray(values)
    if a.size == 0 and a.dtype.kind == "f":
        a = a.astype(np.int64)  # np.asarray([]) is float64; an empty list is no fraction
    if a.dtype.kind not in "iu":
        raise TypeError(f"{name} must hold integers, got an array of {a.dtype}")
    if columns == 1:
        if a.ndim != 1:
            raise ValueError(f"{name} must have shape (k,), got {a.shape}")
    elif a.ndim != 2 or a.shape[1] != columns:
        raise ValueError(f"{name} must have shape (k, {columns}), got {a.shape}")
    if a.size and (a.min() < _INT32_MIN or a.max() > _INT32_MAX):
        raise ValueError(f"{name} holds an index outside int32 ({a.min()} .. {a.max()})")
    _count(a.size, name)
    return np.ascontiguousarray(a, dtype=np.int32)


def _dp(a):
    return None if a is None else a.ctypes.data_as(_double_p)


def _ip(a):
    return None if a is None else a.ctypes.data_as(_int32_p)


def _base(index_base):
    if index_base not in (0, 1):
        raise ValueError(f"index_base must be 0 or 1, got {index_base!r}")
    return int(index_base)


# ------------------------------------------------------------------------- surface

class Surface:
    """One adaptive surface (an sfa_surface handle).

    Surface() is empty; Surface(xyz, tris) sets a mesh at once. Use it as a context
    manager or call close(); an unclosed surface is freed when collected. As in C, one
    surface is for one thread at a time; different surfaces may be used from different
    threads at once (ctypes releases the GIL during every call)."""

    def __init__(self, xyz=None, tris=None, index_base=0, library=None):
        self._h = None
        self._library = load_library(library)
        self._lib = self._library.lib
        # field id -> (components, given as 1-D): the C interface does not tell a field's
        # component count, which get_field needs, and the values go back in their shape.
        self._vertex_fields = {}
        self._face_fields = {}
        handle = _handle()
        rc = self._lib.sfa_create(ctypes.byref(handle))
        if rc != Status.OK:
            raise _ERROR_CLASSES.get(rc, SurfadaptError)(rc, f"sfa_create: {status_string(rc)}", "sfa_create")
        self._h = handle
        # close() may run while the interpreter shuts down, when module globals are
        # already gone: it uses only what the instance holds.
        self._destroy = self._lib.sfa_destroy
        if xyz is not None or tris is not None:
            if xyz is None or tris is None:
                self.close()
                raise ValueError("give both xyz and tris, or neither")
            try:
                self.set_mesh(xyz, tris, index_base)
            except BaseException:
                self.close()
                raise

    # ------------------------------------------------------------------ lifetime
    def close(self):
        """sfa_destroy(). Idempotent; every other method raises StateError afterwards."""
        h, self._h = getattr(self, "_h", None), None
        if h is not None:
            self._destroy(h)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        try:
            self.close()
        except Exception:  # never raise from a finalizer
            pass

    @property
    def closed(self):
        return self._h is None

    def _handle(self):
        if self._h is None:
            raise StateError(Status.ERR_STATE, "the surface is closed", "")
        return self._h

    def _check(self, rc, function):
        if rc != Status.OK:
            message = _text(self._lib.sfa_last_error(self._h)) or f"{function}: {status_string(rc)}"
            raise _ERROR_CLASSES.get(rc, SurfadaptError)(rc, message, function)

    def __repr__(self):
        if self._h is None:
            return "<surfadapt.Surface closed>"
        nv, nt = self.counts
        return f"<surfadapt.Surface {nv} vertices, {nt} triangles>"

    # ------------------------------------------------------------- mesh in and out
    def set_mesh(self, xyz, tris, index_base=0):
        """sfa_set_mesh(): xyz (n, 3) coordinates, tris (m, 3) vertex indices counter-
        clockwise seen from outside, from index_base (0 or 1). Drops the fields and
        velocities of the previous mesh; keeps the parameters. MeshError names the defect."""
        h = self._handle()
        x = _doubles(xyz, "xyz", 3)
        t = _indices(tris, "tris", 3)
        rc = self._lib.sfa_set_mesh(h, x.shape[0], _dp(x), t.shape[0], _ip(t), _base(index_base))
        self._check(rc, "sfa_set_mesh")
        self._vertex_fields.clear()
        self._face_fields.clear()

    @property
    def counts(self):
        """sfa_get_counts(): (vertices, triangles); (0, 0) before a mesh is set."""
        nv, nt = _i32(), _i32()
        self._check(self._lib.sfa_get_counts(self._handle(), ctypes.byref(nv), ctypes.byref(nt)), "sfa_get_counts")
        return nv.value, nt.value

    @property
    def nverts(self):
        return self.counts[0]

    @property
    def ntris(self):
        return self.counts[1]

    def mesh(self, index_base=0):
        """sfa_get_mesh(): (xyz (n, 3) float64, tris (m, 3) int32), new arrays."""
        h = self._handle()
        nv, nt = self.counts
        xyz = np.empty((nv, 3), np.float64)
        tris = np.empty((nt, 3), np.int32)
        self._check(self._lib.sfa_get_mesh(h, nv, _dp(xyz), nt, _ip(tris), _base(index_base)), "sfa_get_mesh")
        return xyz, tris

    # ------------------------------------------------------------------ parameters
    def set_param(self, key, value):
        """sfa_set_param(): key a Param, its number or its name ("edge_length")."""
        h = self._handle()
        self._check(self._lib.sfa_set_param(h, _key(Param, key, "parameter"), float(value)), "sfa_set_param")

    def get_param(self, key):
        """sfa_get_param(): the value of one parameter."""
        h = self._handle()
        v = _dbl()
        self._check(self._lib.sfa_get_param(h, _key(Param, key, "parameter"), ctypes.byref(v)), "sfa_get_param")
        return v.value

    # ---------------------------------------------------------------------- motion
    def set_velocities(self, velocities):
        """sfa_set_velocities_checked(): (n, 3) velocities for the current n vertices; an
        array made for another count (the mesh before adapt()) raises ArgumentError."""
        h = self._handle()
        v = _doubles(velocities, "velocities", 3)
        self._check(self._lib.sfa_set_velocities_checked(h, v.shape[0], _dp(v)), "sfa_set_velocities_checked")

    def move(self, velocities, dt):
        """set_velocities(velocities) (unless None: the ones set before), then sfa_move():
        one explicit step x += dt_taken v. Returns dt_taken <= dt, cut by the fold
        control; call again with the rest of the step."""
        if velocities is not None:
            self.set_velocities(velocities)
        h = self._handle()
        taken = _dbl()
        self._check(self._lib.sfa_move(h, float(dt), ctypes.byref(taken)), "sfa_move")
        return taken.value

    def advect(self, velocity, dt, t=0.0):
        """sfa_advect(): one RK4 step through a velocity field. `velocity(xyz, t)` gets the
        points as an (n, 3) array (a copy, the caller's to keep) and returns their (n, 3)
        velocities. Returns dt_taken <= dt, cut by the fold control.

        An exception raised by `velocity` (or a result of the wrong shape) is raised again
        from advect() once the library has returned, with nothing moved."""
        h = self._handle()
        failure = []

        def trampoline(_ctx, n, xyz_p, time, vel_p):
            vel = np.ctypeslib.as_array(vel_p, shape=(n, 3))
            if failure:
                vel.fill(np.nan)
                return
            try:
                points = np.ctypeslib.as_array(xyz_p, shape=(n, 3)).copy()
                result = np.asarray(velocity(points, time), dtype=np.float64)
                if result.shape != (n, 3):
                    raise ValueError(f"the velocity function returned shape {result.shape} for {n} points; "
                                     f"it must return ({n}, 3)")
                vel[...] = result
            except BaseException as e:  # noqa: B036 - re-raised below, once C has returned
                # An exception cannot cross the C frames, and the callback has no way to
                # report failure: non-finite velocities make sfa_advect refuse the step
                # (SFA_ERR_NUMERIC, nothing moved), and the exception is raised after.
                failure.append(e)
                vel.fill(np.nan)

        callback = VELOCITY_FN(trampoline)  # referenced here until the call returns
        taken = _dbl()
        rc = self._lib.sfa_advect(h, callback, None, float(t), float(dt), ctypes.byref(taken))
        if failure:
            try:
                self._check(rc, "sfa_advect")
            except SurfadaptError as library_error:
                raise failure[0] from library_error
            raise failure[0]
        self._check(rc, "sfa_advect")
        return taken.value

    # ------------------------------------------------------------------ adaptation
    def smooth(self, sweeps=1):
        """sfa_smooth(): `sweeps` anisotropic smoothing sweeps, volume kept."""
        self._check(self._lib.sfa_smooth(self._handle(), int(sweeps)), "sfa_smooth")

    def adapt(self):
        """sfa_adapt(): the full adaptation. Counts change and vertices are renumbered:
        read the mesh and fields back afterwards."""
        self._check(self._lib.sfa_adapt(self._handle()), "sfa_adapt")

    # -------------------------------------------------------------------- analysis
    def measure(self, quantity):
        """sfa_measure(): quantity a Measure, its number or its name ("volume")."""
        h = self._handle()
        v = _dbl()
        self._check(self._lib.sfa_measure(h, _key(Measure, quantity, "quantity"), ctypes.byref(v)), "sfa_measure")
        return v.value

    def feature_ranks(self):
        """sfa_get_feature_ranks(): int32 per vertex, 0 smooth, 1 ridge, 2 corner."""
        h = self._handle()
        ranks = np.empty(self.nverts, np.int32)
        self._check(self._lib.sfa_get_feature_ranks(h, ranks.size, _ip(ranks)), "sfa_get_feature_ranks")
        return ranks

    def vertex_frames(self):
        """sfa_get_vertex_frames(): (normals (n, 3), long_directions (n, 3), aspect_ratios (n,))."""
        h = self._handle()
        n = self.nverts
        normals, longs, ratios = np.empty((n, 3)), np.empty((n, 3)), np.empty(n)
        self._check(self._lib.sfa_get_vertex_frames(h, n, _dp(normals), _dp(longs), _dp(ratios)),
                    "sfa_get_vertex_frames")
        return normals, longs, ratios

    def ridge_edges(self, index_base=0):
        """sfa_get_ridge_edges(): (k, 2) int32, smaller index first, sorted."""
        h = self._handle()
        count = _i32()
        self._check(self._lib.sfa_get_ridge_edges(h, 0, None, ctypes.byref(count), _base(index_base)),
                    "sfa_get_ridge_edges")
        edges = np.empty((count.value, 2), np.int32)
        self._check(self._lib.sfa_get_ridge_edges(h, count.value, _ip(edges), ctypes.byref(count), index_base),
                    "sfa_get_ridge_edges")
        return edges

    # ------------------------------------------------------------------ components
    @property
    def component_count(self):
        """sfa_get_component_count(): bubbles, drops and sheets of the mesh."""
        c = _i32()
        self._check(self._lib.sfa_get_component_count(self._handle(), ctypes.byref(c)), "sfa_get_component_count")
        return c.value

    def components(self):
        """sfa_get_components(): the component (0-based) of every vertex, int32."""
        h = self._handle()
        c = np.empty(self.nverts, np.int32)
        self._check(self._lib.sfa_get_components(h, c.size, _ip(c)), "sfa_get_components")
        return c

    def measure_component(self, component, quantity):
        """sfa_measure_component(): measure() of one component."""
        h = self._handle()
        v = _dbl()
        rc = self._lib.sfa_measure_component(h, int(component), _key(Measure, quantity, "quantity"), ctypes.byref(v))
        self._check(rc, "sfa_measure_component")
        return v.value

    # ---------------------------------------------------------------------- fields
    def add_field(self, values):
        """sfa_add_field_checked(): values (n,) or (n, k) for the n current vertices;
        returns the field's id. The values follow motion, smoothing and adaptation."""
        return self._add(values, self._vertex_fields, self._lib.sfa_add_field_checked, "sfa_add_field_checked")

    def get_field(self, field_id):
        """sfa_get_field(): the field's values on the current vertices, in the shape they
        were added in ((n,) or (n, k))."""
        return self._get(field_id, self._vertex_fields, self.nverts, self._lib.sfa_get_field, "sfa_get_field",
                         "vertex field")

    def set_field(self, field_id, values):
        """sfa_set_field(): replaces the field's values on the n current vertices (after
        the host advanced them over a step), in the shape the field was added in."""
        self._set(field_id, values, self._vertex_fields, self._lib.sfa_set_field, "sfa_set_field", "vertex field")

    def add_face_field(self, values):
        """sfa_add_face_field_checked(): densities (m,) or (m, k) per unit area for the m
        current triangles; returns the face field's id (a sequence of its own)."""
        return self._add(values, self._face_fields, self._lib.sfa_add_face_field_checked,
                         "sfa_add_face_field_checked")

    def get_face_field(self, field_id):
        """sfa_get_face_field(): the densities on the current triangles."""
        return self._get(field_id, self._face_fields, self.ntris, self._lib.sfa_get_face_field,
                         "sfa_get_face_field", "face field")

    def set_face_field(self, field_id, values):
        """sfa_set_face_field(): replaces the densities on the m current triangles; from
        then on smoothing and adaptation keep the new integrals."""
        self._set(field_id, values, self._face_fields, self._lib.sfa_set_face_field, "sfa_set_face_field",
                  "face field")

    def _add(self, values, known, function, name):
        """A vertex or face field added through its _checked function; its width and shape
        recorded in `known` (the C API cannot be asked for them)."""
        h = self._handle()
        v = _doubles(values, "values")
        ncomp = 1 if v.ndim == 1 else v.shape[1]
        fid = _i32()
        self._check(function(h, v.shape[0], ncomp, _dp(v), ctypes.byref(fid)), name)
        known[fid.value] = (ncomp, v.ndim == 1)
        return fid.value

    @staticmethod
    def _shape_of(field_id, known, name, what):
        """(ncomp, flat) of a field this handle added; ArgumentError for another id."""
        if field_id not in known:
            raise ArgumentError(Status.ERR_ARGUMENT, f"{name}: no {what} {field_id!r} on this mesh "
                                f"(ids: {sorted(known)})", name)
        return known[field_id]

    def _get(self, field_id, known, rows, function, name, what):
        h = self._handle()
        ncomp, flat = self._shape_of(field_id, known, name, what)
        out = np.empty((rows, ncomp), np.float64)
        self._check(function(h, int(field_id), out.size, _dp(out)), name)
        return out[:, 0].copy() if flat else out

    def _set(self, field_id, values, known, function, name, what):
        h = self._handle()
        ncomp, flat = self._shape_of(field_id, known, name, what)
        v = _doubles(values, "values")
        if (v.ndim == 1) != flat or (not flat and v.shape[1] != ncomp):
            raise ValueError(f"values must have the shape the {what} was added in, "
                             f"{'(n,)' if flat else f'(n, {ncomp})'}; got {v.shape}")
        self._check(function(h, int(field_id), v.shape[0], _dp(v)), name)

    # ---------------------------------------------------------------- host control
    def set_size_field(self, edge_length):
        """sfa_set_size_field_checked(): a desired edge length (n,) per vertex; None clears it."""
        h = self._handle()
        if edge_length is None:
            self._check(self._lib.sfa_set_size_field_checked(h, self.nverts, None), "sfa_set_size_field_checked")
            return
        v = _doubles(edge_length, "edge_length")
        if v.ndim != 1:
            raise ValueError(f"edge_length must have shape (n,), got {v.shape}")
        self._check(self._lib.sfa_set_size_field_checked(h, v.shape[0], _dp(v)), "sfa_set_size_field_checked")

    def set_fixed_vertices(self, vertices, index_base=0):
        """sfa_set_fixed_vertices(): vertices (k,) that smoothing and adaptation never move
        or remove; replaces the set (empty clears it)."""
        h = self._handle()
        v = _indices(vertices, "vertices", 1)
        self._check(self._lib.sfa_set_fixed_vertices(h, v.shape[0], _ip(v) if v.size else None, _base(index_base)),
                    "sfa_set_fixed_vertices")

    def set_required_edges(self, edges, index_base=0):
        """sfa_set_required_edges(): edges (k, 2) kept exactly; replaces the set."""
        h = self._handle()
        e = _indices(edges, "edges", 2)
        self._check(self._lib.sfa_set_required_edges(h, e.shape[0], _ip(e) if e.size else None, _base(index_base)),
                    "sfa_set_required_edges")

    def vertex_origins(self, index_base=0):
        """sfa_get_vertex_origins(): (triangle (n,) int32 of the mesh before the last
        smooth() or adapt(), barycentric (n, 3) coordinates there)."""
        h = self._handle()
        n = self.nverts
        tri, bary = np.empty(n, np.int32), np.empty((n, 3))
        self._check(self._lib.sfa_get_vertex_origins(h, n, _ip(tri), _dp(bary), _base(index_base)),
                    "sfa_get_vertex_origins")
        return tri, bary


# ----------------------------------------------------------------------- a shape

def icosphere(subdivisions=3, radius=1.0, center=(0.0, 0.0, 0.0)):
    """A sphere to start from: the icosahedron with each triangle split in four
    `subdivisions` times and the vertices pushed onto the sphere; 10 * 4^k + 2 vertices,
    triangles counter-clockwise seen from outside. Returns (xyz (n, 3), tris (m, 3) int32)."""
    p = (1.0 + 5.0 ** 0.5) / 2.0
    xyz = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p),
           (0, -1, -p), (0, 1, -p), (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    xyz = [np.array(v, float) / np.linalg.norm(v) for v in xyz]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
            (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
            (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(int(subdivisions)):
        midpoint = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                m = xyz[a] + xyz[b]
                xyz.append(m / np.linalg.norm(m))
                midpoint[key] = len(xyz) - 1
            return midpoint[key]

        finer = []
        for a, b, c in tris:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = finer
    points = np.array(xyz) * float(radius) + np.asarray(center, float)
    return points, np.array(tris, np.int32)
