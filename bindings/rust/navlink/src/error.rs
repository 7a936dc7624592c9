//! Statuses as `Result`s.
use navlink_sys as sys;
use std::ffi::CStr;
use std::fmt;
use std::os::raw::c_char;

/// A failed call: its `nl_status` and the library's message (the calling thread's last error, read
/// right after the call).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    status: u32,
    message: String,
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// The last error of this thread, for a call that just returned `status`.
    pub(crate) fn last(status: u32) -> Error {
        Error { status, message: unsafe { borrowed_str(sys::nl_get_last_error_message()) } }
    }

    /// A failure found by the binding before calling the library (e.g. a string with a NUL byte).
    pub(crate) fn binding(status_bits: u32, message: String) -> Error {
        Error { status: sys::NL_STATUS_FAILURE | status_bits, message }
    }

    pub fn status(&self) -> u32 {
        self.status
    }

    pub fn message(&self) -> &str {
        &self.message
    }

    /// True if the status carries this detail bit (`status::INVALID_HANDLE`...).
    pub fn has(&self, bit: u32) -> bool {
        self.status & bit != 0
    }

    /// What went wrong, from the status's detail bits (the first of `ERROR_KINDS` that is set).
    pub fn kind(&self) -> ErrorKind {
        ERROR_KINDS.iter().find(|(bit, _)| self.has(*bit)).map_or(ErrorKind::Other, |(_, kind)| *kind)
    }
}

/// What went wrong in a failed call: the detail of its `nl_status`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    InvalidArgument,
    /// A stale or null id or ticket (removed, released, or another world's).
    InvalidHandle,
    BufferTooSmall,
    OutOfMemory,
    Cancelled,
    NotFound,
    Internal,
    Io,
    Parse,
    /// Not a NavLink file, or a newer format, or a plugin for another ABI.
    VersionMismatch,
    /// A detail this binding has no name for (a newer library's), or none.
    Other,
}

/// Detail bits to kinds, in the order `Error::kind` looks (a status may carry several: the caller's
/// mistake comes before what followed from it).
const ERROR_KINDS: [(u32, ErrorKind); 10] = [
    (sys::NL_STATUS_INVALID_HANDLE, ErrorKind::InvalidHandle),
    (sys::NL_STATUS_INVALID_ARGUMENT, ErrorKind::InvalidArgument),
    (sys::NL_STATUS_BUFFER_TOO_SMALL, ErrorKind::BufferTooSmall),
    (sys::NL_STATUS_OUT_OF_MEMORY, ErrorKind::OutOfMemory),
    (sys::NL_STATUS_CANCELLED, ErrorKind::Cancelled),
    (sys::NL_STATUS_NOT_FOUND, ErrorKind::NotFound),
    (sys::NL_STATUS_IO_ERROR, ErrorKind::Io),
    (sys::NL_STATUS_PARSE_ERROR, ErrorKind::Parse),
    (sys::NL_STATUS_VERSION_MISMATCH, ErrorKind::VersionMismatch),
    (sys::NL_STATUS_INTERNAL_ERROR, ErrorKind::Internal),
];

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.message, status_string(self.status))
    }
}

impl std::error::Error for Error {}

/// `Ok(status)` unless the status is a failure (a success may carry PARTIAL_RESULT, or be IN_PROGRESS).
pub(crate) fn check(status: u32) -> Result<u32> {
    if sys::nl_failed(status) {
        Err(Error::last(status))
    } else {
        Ok(status)
    }
}

/// `nl_status_string`: "failure: invalid argument".
pub fn status_string(status: u32) -> &'static str {
    // A static string owned by the library, ASCII.
    unsafe { CStr::from_ptr(sys::nl_status_string(status)) }.to_str().unwrap_or("?")
}

/// Copies a borrowed NUL-terminated UTF-8 string ("" for null).
pub(crate) unsafe fn borrowed_str(p: *const c_char) -> String {
    if p.is_null() {
        String::new()
    } else {
        CStr::from_ptr(p).to_string_lossy().into_owned()
    }
}
