"""The base classes of the ctypes structs in _navlink_abi.py (generated): field-naming reprs, output structs
that set their own ``size``, ids that print as slot and revision, and fields read as the header's kinds."""
import ctypes
import enum
from ctypes import Structure, c_uint32, c_void_p, sizeof
from typing import Any


def _shown(value: Any) -> str:
    """A field's value as a struct's repr shows it: enum members by name, floats short, fixed arrays as
    tuples, pointers as NULL or an address."""
    if isinstance(value, enum.Enum):
        return value.name
    if isinstance(value, float):
        return "%.6g" % value
    if isinstance(value, ctypes.Array):
        return "(%s)" % ", ".join(_shown(v) for v in value)
    if isinstance(value, (ctypes._Pointer, ctypes._CFuncPtr)):  # type: ignore[attr-defined]
        return "0x%x" % ctypes.cast(value, c_void_p).value if value else "NULL"
    return repr(value)


class _Struct(Structure):
    """A C struct whose repr names its fields and their values (without size and reserved ones)."""

    def __repr__(self) -> str:
        shown = ["%s=%s" % (name, _shown(getattr(self, name))) for name, *_ in self._fields_
                 if name != "size" and not name.startswith("reserved")]
        return "%s(%s)" % (type(self).__name__, ", ".join(shown))


class _EnumField:
    """A struct field of one of the header's kinds, read as a member of its IntEnum (or the number itself, for
    a value newer than this module) and written as a number. Keeps the ctypes field's offset and size."""

    def __init__(self, field: Any, kind: Any) -> None:
        self.field = field
        self.kind = kind
        self.offset, self.size = field.offset, field.size
        self.members = {member.value: member for member in kind}

    def __get__(self, struct: Any, owner: Any = None) -> Any:
        if struct is None:
            return self
        value = self.field.__get__(struct, owner)
        return self.members.get(value, value)

    def __set__(self, struct: Any, value: Any) -> None:
        self.field.__set__(struct, value)


def _read_as_enums(struct_type: Any, **kinds: Any) -> None:
    """Makes the named fields of struct_type read as their IntEnums."""
    for name, kind in kinds.items():
        setattr(struct_type, name, _EnumField(struct_type.__dict__[name], kind))


class _Growable(_Struct):
    """An output struct that may grow (``size`` first). A new one has ``size`` set to this module's
    sizeof, as the header's nl_*_init() does, unless a size or positional values are given."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        if not args and "size" not in kwargs:
            self.size = sizeof(self)


class _Id(_Struct):
    """An id ({index1, revision}, passed by value). Prints as MeshId(index=3, revision=1): the slot index
    and how many times the slot has been used, read from the two fields (MeshId(null) for the null id)."""
    _fields_ = [("index1", c_uint32), ("revision", c_uint32)]
    # docs/c-api.md, "Ids": index1's low 28 bits are the slot index + 1 (its top 4 the kind of object), and
    # revision's low 20 bits count the slot's reuse (its top 12 name the world). For reading ids only.
    _SLOT_MASK = (1 << 28) - 1
    _REVISION_MASK = (1 << 20) - 1

    def __eq__(self, other: object) -> bool:
        if type(self) is not type(other):
            return NotImplemented  # lets a PathRequest compare itself with its PathTicket
        return (self.index1, self.revision) == (other.index1, other.revision)  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash((type(self).__name__, self.index1, self.revision))

    def __repr__(self) -> str:
        if self.is_null:
            return "%s(null)" % type(self).__name__
        return "%s(index=%d, revision=%d)" % (
            type(self).__name__, self.slot_index, self.revision & self._REVISION_MASK)

    @property
    def is_null(self) -> bool:
        return self.index1 == 0

    @property
    def slot_index(self) -> int:
        """The index of the object's slot, from 0 (-1 for the null id): what the repr shows, for reading only."""
        return (self.index1 & self._SLOT_MASK) - 1
