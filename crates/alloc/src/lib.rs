//! The binaries' global allocator: [`System`], with every block of at
//! least [`ADVISE_FROM`] bytes advised to the kernel as transparent huge
//! pages (`madvise(MADV_HUGEPAGE)`, Linux only; elsewhere the allocator
//! is `System` as it is).
//!
//! Why: where the kernel's THP mode is `madvise` (Debian's default), each
//! 4 KiB page of a large array is faulted in and zeroed on its own. The
//! extraction's arrays (tens to hundreds of MB) spent 5–20 % of the
//! process's time in the kernel; advised, they fault 2 MiB at a time
//! (BENCHMARKS.md, "Huge pages for the large arrays").
//!
//! Input and output: those of [`System`]; every pointer comes from it
//! and goes back to it with the caller's layout. The advice is a hint:
//! it never changes the memory's contents, and its failure is ignored.
//! Invariant: only whole huge pages inside the block just (re)allocated
//! are advised ([`inside`]).

use std::alloc::{GlobalAlloc, Layout, System};

/// The system allocator, large blocks advised as huge pages (module docs).
pub struct HugePages;

/// A transparent huge page on x86-64 and aarch64 with 4 KiB pages.
const HUGE: usize = 2 << 20;

/// Blocks from this size on are advised (two huge pages: a smaller block
/// seldom holds a whole aligned one).
pub const ADVISE_FROM: usize = 2 * HUGE;

/// The whole huge pages inside the block of `len` bytes at address `at`:
/// their start and length, or `None` for none.
pub fn inside(at: usize, len: usize) -> Option<(usize, usize)> {
    let start = at.checked_next_multiple_of(HUGE)?;
    let end = at.checked_add(len)? & !(HUGE - 1);
    (end > start).then(|| (start, end - start))
}

/// Advises the huge pages inside the block `p` of `len` bytes (nothing for
/// a null `p` or a small block).
fn advise(p: *mut u8, len: usize) {
    if p.is_null() || len < ADVISE_FROM {
        return;
    }
    if let Some((start, len)) = inside(p as usize, len) {
        hint(start, len);
    }
}

/// `madvise(MADV_HUGEPAGE)` on `len` bytes at `start` (a hint: its result
/// is ignored).
#[cfg(target_os = "linux")]
fn hint(start: usize, len: usize) {
    // SAFETY: [start, start + len) lies inside a block the allocator just
    // handed out ([`inside`]); MADV_HUGEPAGE changes how its pages are
    // backed, never their contents, and touches no other mapping.
    unsafe {
        libc::madvise(start as *mut libc::c_void, len, libc::MADV_HUGEPAGE);
    }
}

/// No advice off Linux.
#[cfg(not(target_os = "linux"))]
fn hint(_: usize, _: usize) {}

// SAFETY: every call is forwarded to `System` with the caller's arguments;
// `advise` only hints at pages inside the block returned.
unsafe impl GlobalAlloc for HugePages {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract, forwarded.
        let p = unsafe { System.alloc(layout) };
        advise(p, layout.size());
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract, forwarded.
        let p = unsafe { System.alloc_zeroed(layout) };
        advise(p, layout.size());
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        // SAFETY: the caller's contract, forwarded.
        unsafe { System.dealloc(p, layout) }
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, size: usize) -> *mut u8 {
        // SAFETY: the caller's contract, forwarded.
        let q = unsafe { System.realloc(p, layout, size) };
        advise(q, size);
        q
    }
}

#[cfg(test)]
mod tests;
