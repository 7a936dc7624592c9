//! navlink.h's function-like macros over a status, which the generator does not read (it reads constants,
//! types and functions): `NL_SUCCEEDED(status)` and `NL_FAILED(status)`.
use crate::constants_generated::{nl_status, NL_STATUS_FAILURE, NL_STATUS_SUCCESS};

/// `NL_SUCCEEDED(status)`.
pub const fn nl_succeeded(status: nl_status) -> bool {
    status & NL_STATUS_SUCCESS != 0
}

/// `NL_FAILED(status)`.
pub const fn nl_failed(status: nl_status) -> bool {
    status & NL_STATUS_FAILURE != 0
}
