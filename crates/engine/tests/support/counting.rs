//! A counting global allocator for the allocation tests (issue 17 "verify with a counting
//! allocator in a test"): the system allocator, counting allocations and reallocations.
//! Including this module makes it the test binary's allocator. Each thread keeps its own count
//! and [`allocations`] reads the calling thread's: the test harness's main thread allocates while
//! it prints one test's result and spawns the next, which a process-wide counter charged to
//! whichever test was counting then (a failure seen once under load in the osi target). The
//! engine's step and the sinks run on the calling thread (neither uses a thread pool), so
//! nothing of theirs is missed; such a binary's tests still run one at a time ([`SERIAL`]).

#![allow(dead_code)] // each target uses a different part

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::Mutex;

/// The system allocator, counting allocations and reallocations.
pub struct Counting;

thread_local! {
    /// Allocations and reallocations made by this thread (const-initialised, no destructor:
    /// reading it never allocates).
    static ALLOCATIONS: Cell<u64> = const { Cell::new(0) };
}

/// One more allocation of this thread (none counted while the thread is being torn down).
fn count() {
    let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
}

/// This thread's allocations so far.
fn counted() -> u64 {
    ALLOCATIONS.try_with(Cell::get).unwrap_or(0)
}

// SAFETY: every call is forwarded unchanged to the system allocator; the counter is atomic.
// Counting allocations needs a global allocator, an unsafe trait: the workspace lint
// `unsafe_code` is allowed here only.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: the caller's contract is passed on.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// One test at a time: the counter is global.
pub static SERIAL: Mutex<()> = Mutex::new(());

/// Holds [`SERIAL`] (a test that panicked while holding it does not stop the others).
pub fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

/// Allocations made by `f` on the calling thread.
pub fn allocations(f: impl FnOnce()) -> u64 {
    let before = counted();
    f();
    counted() - before
}
