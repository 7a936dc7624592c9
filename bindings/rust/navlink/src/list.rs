//! The header's two-call pattern for lists.
use crate::error::{check, Result};
use navlink_sys as sys;

/// Asks the count (null buffer), then fills a buffer of that size. The list may grow in between
/// (another thread adds to it): BUFFER_TOO_SMALL then, and we ask again. The buffer holds `T::default()`,
/// which for growable C elements (`nl_link`) sets the `size` the library reads the element size from.
pub(crate) fn two_call<T: Clone + Default>(mut call: impl FnMut(*mut T, u32, &mut u32) -> u32) -> Result<Vec<T>> {
    loop {
        let mut count = 0u32;
        check(call(std::ptr::null_mut(), 0, &mut count))?;
        let mut items = vec![T::default(); count as usize];
        if count == 0 {
            return Ok(items);
        }
        let status = call(items.as_mut_ptr(), count, &mut count);
        if sys::nl_failed(status) && status & sys::NL_STATUS_BUFFER_TOO_SMALL != 0 {
            continue;
        }
        check(status)?;
        items.truncate(count as usize);
        return Ok(items);
    }
}

/// `two_call` over C elements, each turned into its plain Rust struct.
pub(crate) fn two_call_as<C: Clone + Default, R: From<C>>(call: impl FnMut(*mut C, u32, &mut u32) -> u32) -> Result<Vec<R>> {
    Ok(two_call(call)?.into_iter().map(R::from).collect())
}
