//! navlink.h: "Version" and "Status".
use std::os::raw::c_char;

/// The version of the header these bindings were written from (`navlink/version.h`).
pub const NL_VERSION_MAJOR: i32 = 0;
pub const NL_VERSION_MINOR: i32 = 2;
pub const NL_VERSION_PATCH: i32 = 0;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct nl_version {
    pub major: i32,
    pub minor: i32,
    pub patch: i32,
}

pub type nl_status = u32;

pub const NL_STATUS_FAILURE: nl_status = 0x8000_0000;
pub const NL_STATUS_SUCCESS: nl_status = 0x4000_0000;
pub const NL_STATUS_IN_PROGRESS: nl_status = 0x2000_0000;
pub const NL_STATUS_DETAIL_MASK: nl_status = 0x0fff_ffff;

pub const NL_STATUS_INVALID_ARGUMENT: nl_status = 0x0000_0001;
pub const NL_STATUS_INVALID_HANDLE: nl_status = 0x0000_0002;
pub const NL_STATUS_BUFFER_TOO_SMALL: nl_status = 0x0000_0004;
pub const NL_STATUS_OUT_OF_MEMORY: nl_status = 0x0000_0008;
pub const NL_STATUS_CANCELLED: nl_status = 0x0000_0010;
pub const NL_STATUS_PARTIAL_RESULT: nl_status = 0x0000_0020;
pub const NL_STATUS_NOT_FOUND: nl_status = 0x0000_0040;
pub const NL_STATUS_INTERNAL_ERROR: nl_status = 0x0000_0080;
pub const NL_STATUS_IO_ERROR: nl_status = 0x0000_0100;
pub const NL_STATUS_PARSE_ERROR: nl_status = 0x0000_0200;
pub const NL_STATUS_VERSION_MISMATCH: nl_status = 0x0000_0400;

/// `NL_SUCCEEDED(status)`.
pub const fn nl_succeeded(status: nl_status) -> bool {
    status & NL_STATUS_SUCCESS != 0
}

/// `NL_FAILED(status)`.
pub const fn nl_failed(status: nl_status) -> bool {
    status & NL_STATUS_FAILURE != 0
}

pub const NL_COORDINATE_LIMIT: f32 = 1.0e9;

extern "C" {
    pub fn nl_get_version() -> nl_version;
    /// Static string owned by the library.
    pub fn nl_status_string(status: nl_status) -> *const c_char;
    pub fn nl_get_last_status() -> nl_status;
    /// Borrowed until this thread's next nl_* call; never null.
    pub fn nl_get_last_error_message() -> *const c_char;
}
