//! Status codes and the error message of the last failed call.
//!
//! Every function of the C API returns an [`OscsimStatus`]; on anything but
//! [`OscsimStatus::Ok`] the calling thread's last error message (with `file:line:col` when the
//! error has a place in a scenario or road file) is kept until the next failing call and read
//! with [`oscsim_last_error_message`]. Every call runs inside [`guard`], which turns a Rust
//! panic into [`OscsimStatus::Panic`]: a panic never unwinds into C and never aborts.

use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The result of a call.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OscsimStatus {
    /// Success.
    Ok = 0,
    /// The scenario, a catalog, a parameter value or the road network did not load, or the
    /// engine could not be built from it; the message names file:line:col.
    Load = 1,
    /// A step failed (an action that cannot start, a non-finite state); the simulation refuses
    /// further steps.
    Step = 2,
    /// An argument is invalid: a null pointer, text that is not UTF-8, a non-finite number, an
    /// index out of range.
    Argument = 3,
    /// No entity of that name is in the scenario.
    NotFound = 4,
    /// The entity is not driven by an `external` controller.
    NotExternal = 5,
    /// oscsim panicked (a bug). The call failed; a simulation that panicked mid-call refuses
    /// further use. The program goes on.
    Panic = 6,
}

/// A failed call: its status and message.
#[derive(Debug, Clone)]
pub struct Failure {
    /// The status returned to C.
    pub status: OscsimStatus,
    /// The message kept for [`oscsim_last_error_message`].
    pub message: String,
}

impl Failure {
    /// A failure of `status` with `message`.
    pub fn new(status: OscsimStatus, message: impl Into<String>) -> Self {
        Failure {
            status,
            message: message.into(),
        }
    }

    /// An [`OscsimStatus::Argument`] failure.
    pub fn argument(message: impl Into<String>) -> Self {
        Failure::new(OscsimStatus::Argument, message)
    }
}

thread_local! {
    /// The message of the calling thread's last failed call.
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

fn set_last_error(message: &str) {
    // Interior NULs cannot go into a C string; they become spaces.
    let text = CString::new(message.replace('\0', " "))
        .unwrap_or_else(|_| CString::from(c"error message with NUL"));
    LAST_ERROR.with(|slot| *slot.borrow_mut() = text);
}

/// Runs `f`, turning its failure into a status and the last error message, and a panic into
/// [`OscsimStatus::Panic`].
pub fn guard(f: impl FnOnce() -> Result<(), Failure>) -> OscsimStatus {
    let outcome = catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without message".to_owned());
        Err(Failure::new(
            OscsimStatus::Panic,
            format!("internal error in oscsim (please report it): {message}"),
        ))
    });
    match outcome {
        Ok(()) => OscsimStatus::Ok,
        Err(failure) => {
            set_last_error(&failure.message);
            failure.status
        }
    }
}

/// The message of the calling thread's last failed call (empty before any failed): UTF-8,
/// NUL-terminated, owned by the library and valid until the thread's next failing call.
#[no_mangle]
pub extern "C" fn oscsim_last_error_message() -> *const c_char {
    LAST_ERROR.with(|slot| slot.borrow().as_ptr())
}

/// Panics inside oscsim, for tests of the boundary: returns [`OscsimStatus::Panic`] with a
/// message that contains `oscsim_test_panic`; the program goes on.
#[no_mangle]
pub extern "C" fn oscsim_test_panic() -> OscsimStatus {
    guard(|| panic!("oscsim_test_panic was called"))
}
