//! The `extern "C"` functions the library calls back, one per callback type. Each finds its closure
//! through the `user` pointer and runs it inside `catch_unwind`: unwinding into C is undefined
//! behaviour, so a panic is either carried back to the caller's thread (progress) or reported on
//! stderr (log and path callbacks, which may run on a NavLink worker with nobody to resume it).
use crate::error::{borrowed_str, check, Result};
use crate::kinds::PathOutcome;
use crate::paths::{fill_finished_slot, FinishedSlot};
use crate::types::PathTicket;
use navlink_sys as sys;
use std::any::Any;
use std::os::raw::{c_char, c_void};
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::ptr;
use std::sync::{Arc, Mutex};

/// What the log callback's `user` points to.
pub(crate) type LogBox = Box<dyn Fn(u32, u32, &str) + Send + Sync>;

pub(crate) unsafe extern "C" fn log(user: *mut c_void, level: u32, status: u32, message: *const c_char) {
    let handler = &*(user as *const LogBox);
    let message = borrowed_str(message);
    if catch_unwind(AssertUnwindSafe(|| handler(level, status, &message))).is_err() {
        eprintln!("navlink: the log callback panicked (ignored)");
    }
}

/// Progress of a link generation or a navmesh build: (fraction done, stage name) -> go on? Called on the
/// thread that made the call.
pub type Progress<'a> = &'a mut dyn FnMut(f32, &str) -> bool;

/// The state of one call's progress callback: the closure, and a panic to resume after the call.
struct ProgressContext<'a> {
    handler: Progress<'a>,
    panic: Option<Box<dyn Any + Send>>,
}

/// Runs a call that takes an `nl_progress_fn` and its user pointer with an optional progress closure; a
/// panic in the closure cancels the call and resumes here, once the C call has returned.
pub(crate) fn with_progress(handler: Option<Progress<'_>>, call: impl FnOnce(sys::nl_progress_fn, *mut c_void) -> u32) -> Result<()> {
    let handler = match handler {
        None => return check(call(None, ptr::null_mut())).map(drop),
        Some(handler) => handler,
    };
    let mut context = ProgressContext { handler, panic: None };
    let status = call(Some(progress), &mut context as *mut ProgressContext as *mut c_void);
    let result = check(status).map(drop);
    if let Some(panic) = context.panic.take() {
        resume_unwind(panic);
    }
    result
}

unsafe extern "C" fn progress(user: *mut c_void, fraction: f32, stage: *const c_char) -> i32 {
    let context = &mut *(user as *mut ProgressContext);
    if context.panic.is_some() {
        return 0;
    }
    let stage = borrowed_str(stage);
    let handler = &mut context.handler;
    match catch_unwind(AssertUnwindSafe(|| handler(fraction, &stage))) {
        Ok(go_on) => go_on as i32,
        Err(panic) => {
            // Cancel the call; with_progress resumes the panic once the C call has returned.
            context.panic = Some(panic);
            0
        }
    }
}

/// A user's path closure: called once, on whatever thread finishes the request.
pub(crate) type PathBox = Box<dyn FnOnce(PathTicket, PathOutcome) + Send>;

/// What a path request's `user` points to: called back once, then freed.
pub(crate) struct PathCallback {
    /// Read by the request's `Future`.
    pub finished: Arc<Mutex<FinishedSlot>>,
    pub on_finished: Option<PathBox>,
}

pub(crate) unsafe extern "C" fn path_finished(user: *mut c_void, ticket: PathTicket, outcome: u32) {
    // navlink.h: exactly once per accepted request, so the box is taken back here.
    let callback: Box<PathCallback> = Box::from_raw(user as *mut PathCallback);
    let outcome = PathOutcome::from_raw(outcome);
    // The closure first: a task woken by the slot finds what the closure did already done.
    if let Some(handler) = callback.on_finished {
        if catch_unwind(AssertUnwindSafe(move || handler(ticket, outcome))).is_err() {
            eprintln!("navlink: a path callback panicked (ignored; the request finished normally)");
        }
    }
    // A waker is foreign code: it must not unwind into C either.
    if catch_unwind(AssertUnwindSafe(|| fill_finished_slot(&callback.finished, outcome))).is_err() {
        eprintln!("navlink: waking a path request's task panicked (ignored)");
    }
}
