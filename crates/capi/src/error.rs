//! Status codes, the thread-local last error message, and the guard that
//! keeps panics from crossing the C boundary.
//!
//! Input: the body of one entry point as a closure returning
//! `Result<(), Failure>`. Output: a status code; the message of a failure
//! (or of a caught panic, prefixed `internal error (bug): `) is stored for
//! `dualex_last_error()`, an ok result clears it.

use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The return code of every entry point (`int` in C).
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DualexStatus {
    /// Success.
    Ok = 0,
    /// A null or misaligned pointer, or a size whose byte count overflows.
    InvalidArgument = 1,
    /// The map is invalid or refused (index out of range, NaN, …).
    InvalidInput = 2,
    /// The extraction could not make a valid mesh, or (with `strict`) the
    /// output's topology differs from the input's or inverted elements
    /// remain after the geometric stage.
    ExtractionFailed = 3,
    /// A bug: a panic caught at the boundary.
    Internal = 4,
}

/// A failed call: its status code and message.
pub(crate) struct Failure {
    pub status: DualexStatus,
    pub message: String,
}

impl Failure {
    /// A bad argument (null pointer, size overflow).
    pub fn argument(message: impl Into<String>) -> Self {
        Failure {
            status: DualexStatus::InvalidArgument,
            message: message.into(),
        }
    }
}

impl From<dualex::Error> for Failure {
    fn from(e: dualex::Error) -> Self {
        let status = match e {
            dualex::Error::Input(_) => DualexStatus::InvalidInput,
            _ => DualexStatus::ExtractionFailed,
        };
        Failure {
            status,
            message: e.to_string(),
        }
    }
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

fn set_last_error(message: &str) {
    // an interior NUL would cut the C string: replace it
    let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
    LAST_ERROR.with(|e| *e.borrow_mut() = text);
}

/// Runs one entry point's body: panics caught, the message stored.
pub(crate) fn guard(body: impl FnOnce() -> Result<(), Failure>) -> i32 {
    let result = catch_unwind(AssertUnwindSafe(body)).unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_string());
        Err(Failure {
            status: DualexStatus::Internal,
            message: format!("internal error (bug): {what}; please report the input"),
        })
    });
    match result {
        Ok(()) => {
            set_last_error("");
            DualexStatus::Ok as i32
        }
        Err(f) => {
            set_last_error(&f.message);
            f.status as i32
        }
    }
}

/// The last error message of the calling thread (`""` after a success),
/// valid until this thread's next call into the library.
#[no_mangle]
pub extern "C" fn dualex_last_error() -> *const c_char {
    LAST_ERROR.with(|e| e.borrow().as_ptr())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::CStr;

    fn last() -> String {
        // SAFETY: the pointer is this thread's CString, alive until the next call
        unsafe { CStr::from_ptr(dualex_last_error()) }
            .to_string_lossy()
            .into_owned()
    }

    #[test]
    fn a_panic_is_an_internal_error_with_its_message() {
        let code = guard(|| panic!("boom"));
        assert_eq!(code, DualexStatus::Internal as i32);
        assert_eq!(
            last(),
            "internal error (bug): boom; please report the input"
        );
        assert_eq!(guard(|| Ok(())), 0);
        assert_eq!(last(), "");
        let code = guard(|| Err(Failure::argument("a\0b")));
        assert_eq!(code, DualexStatus::InvalidArgument as i32);
        assert_eq!(last(), "a b");
    }
}
