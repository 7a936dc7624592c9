//! Statuses as `Result`s.
use navlink_sys as sys;
use std::ffi::CStr;
use std::fmt;
use std::os::raw::c_char;

/// A failed call: its `nl_status` and the library's message (the calling thread's last error, read
/// right after the call). `Debug` names the status's bits:
/// `Error { status: Status(FAILURE | NOT_FOUND), message: "..." }`.
#[derive(Clone, PartialEq, Eq)]
pub struct Error {
    status: u32,
    message: String,
}

impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Error").field("status", &Status(self.status)).field("message", &self.message).finish()
    }
}

/// An `nl_status` as a value that prints by name: `Debug` lists its bits, `Status(FAILURE | INVALID_ARGUMENT)`
/// (a bit this binding has no name for in hex), and `Display` is the library's `nl_status_string`
/// ("failure: invalid argument"). `PathSummary::status` is one; `Error::status()` is the raw `u32`
/// (`Status(error.status())` prints it by name). Test bits with `has(status::NOT_FOUND)`; it equals its `u32`.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Status(pub u32);

/// The named bits of an `nl_status`, in the order `Debug` lists them.
const STATUS_NAMES: [(u32, &str); 14] = [
    (sys::NL_STATUS_FAILURE, "FAILURE"),
    (sys::NL_STATUS_SUCCESS, "SUCCESS"),
    (sys::NL_STATUS_IN_PROGRESS, "IN_PROGRESS"),
    (sys::NL_STATUS_INVALID_ARGUMENT, "INVALID_ARGUMENT"),
    (sys::NL_STATUS_INVALID_HANDLE, "INVALID_HANDLE"),
    (sys::NL_STATUS_BUFFER_TOO_SMALL, "BUFFER_TOO_SMALL"),
    (sys::NL_STATUS_OUT_OF_MEMORY, "OUT_OF_MEMORY"),
    (sys::NL_STATUS_CANCELLED, "CANCELLED"),
    (sys::NL_STATUS_PARTIAL_RESULT, "PARTIAL_RESULT"),
    (sys::NL_STATUS_NOT_FOUND, "NOT_FOUND"),
    (sys::NL_STATUS_INTERNAL_ERROR, "INTERNAL_ERROR"),
    (sys::NL_STATUS_IO_ERROR, "IO_ERROR"),
    (sys::NL_STATUS_PARSE_ERROR, "PARSE_ERROR"),
    (sys::NL_STATUS_VERSION_MISMATCH, "VERSION_MISMATCH"),
];

impl Status {
    /// The raw `nl_status`.
    pub const fn bits(self) -> u32 {
        self.0
    }

    /// True if the status carries this bit (`status::FAILURE`, `status::PARTIAL_RESULT`...).
    pub const fn has(self, bit: u32) -> bool {
        self.0 & bit != 0
    }

    /// `NL_FAILED(status)`.
    pub const fn is_failure(self) -> bool {
        sys::nl_failed(self.0)
    }

    /// `NL_SUCCEEDED(status)` (a success may carry PARTIAL_RESULT).
    pub const fn is_success(self) -> bool {
        sys::nl_succeeded(self.0)
    }
}

impl fmt::Debug for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Status(")?;
        let mut rest = self.0;
        let mut first = true;
        for (bit, name) in STATUS_NAMES {
            if rest & bit != 0 {
                write!(f, "{}{}", if first { "" } else { " | " }, name)?;
                rest &= !bit;
                first = false;
            }
        }
        if rest != 0 {
            write!(f, "{}{:#x}", if first { "" } else { " | " }, rest)?;
        } else if first {
            f.write_str("0")?;
        }
        f.write_str(")")
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(status_string(self.0))
    }
}

impl From<u32> for Status {
    fn from(bits: u32) -> Status {
        Status(bits)
    }
}

impl From<Status> for u32 {
    fn from(status: Status) -> u32 {
        status.0
    }
}

impl PartialEq<u32> for Status {
    fn eq(&self, bits: &u32) -> bool {
        self.0 == *bits
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statuses_debug_by_name() {
        let failure = Status(sys::NL_STATUS_FAILURE | sys::NL_STATUS_INVALID_ARGUMENT);
        assert_eq!(format!("{:?}", failure), "Status(FAILURE | INVALID_ARGUMENT)");
        assert_eq!(format!("{:?}", Status(sys::NL_STATUS_SUCCESS)), "Status(SUCCESS)");
        assert_eq!(format!("{:?}", Status(sys::NL_STATUS_SUCCESS | sys::NL_STATUS_PARTIAL_RESULT)), "Status(SUCCESS | PARTIAL_RESULT)");
        assert_eq!(format!("{:?}", Status(sys::NL_STATUS_IN_PROGRESS)), "Status(IN_PROGRESS)");
        assert_eq!(
            format!("{:?}", Status(sys::NL_STATUS_FAILURE | sys::NL_STATUS_NOT_FOUND | sys::NL_STATUS_IO_ERROR)),
            "Status(FAILURE | NOT_FOUND | IO_ERROR)"
        );
        // A detail bit a newer library may add, and no bit at all.
        assert_eq!(format!("{:?}", Status(sys::NL_STATUS_FAILURE | 0x800)), "Status(FAILURE | 0x800)");
        assert_eq!(format!("{:?}", Status(0)), "Status(0)");
        assert!(failure.is_failure() && !failure.is_success() && failure.has(sys::NL_STATUS_INVALID_ARGUMENT));
        assert!(failure == sys::NL_STATUS_FAILURE | sys::NL_STATUS_INVALID_ARGUMENT && u32::from(failure) == failure.bits());
    }

    #[test]
    fn statuses_display_as_the_library_says() {
        let failure = Status(sys::NL_STATUS_FAILURE | sys::NL_STATUS_INVALID_HANDLE);
        assert_eq!(failure.to_string(), status_string(failure.bits()));
        assert!(failure.to_string().contains("invalid handle"), "{}", failure);
    }

    #[test]
    fn path_summaries_debug_their_status_by_name() {
        let summary = crate::PathSummary { status: Status(sys::NL_STATUS_SUCCESS), ..Default::default() };
        assert!(format!("{:?}", summary).contains("status: Status(SUCCESS),"), "{:?}", summary);
        assert!(summary.status == sys::NL_STATUS_SUCCESS);
    }

    #[test]
    fn errors_debug_their_status_by_name() {
        let error = Error::binding(sys::NL_STATUS_INVALID_ARGUMENT, "path: a NUL byte".to_string());
        assert_eq!(format!("{:?}", error), "Error { status: Status(FAILURE | INVALID_ARGUMENT), message: \"path: a NUL byte\" }");
    }
}
