//! The binaries' global allocator: [`System`] for small blocks; blocks of
//! at least [`LARGE_FROM`] bytes (Linux) carved by the allocator itself
//! from arenas it maps and advises as transparent huge pages
//! (`madvise(MADV_HUGEPAGE)`), and kept when freed for the next large
//! block (`cache`). Elsewhere the allocator is `System` as it is.
//!
//! Why: a page the kernel hands out fresh is faulted in and zeroed on its
//! first touch, 4 KiB at a time unless advised as a huge page (Debian's THP
//! mode is `madvise`), and a 4 KiB fault costs about three times the same
//! bytes in a huge page. The extraction's stages each allocate their arrays
//! anew (tens to hundreds of MB): that cost a third of the process's CPU
//! time on torus537 (BENCHMARKS.md, "Huge pages for the large arrays" and
//! "Large blocks kept for the next stage").
//!
//! Input and output: those of [`GlobalAlloc`]. A small block comes from
//! and goes back to `System` with the caller's layout; a large one is the
//! cache's from its allocation to its release. Invariants: only whole huge
//! pages inside a fresh mapping are advised ([`inside`]); the cache raises
//! the peak of the resident memory only by the huge pages' granularity
//! (the `cache` module's docs).

use std::alloc::{GlobalAlloc, Layout, System};

/// The system allocator for small blocks, the cache for large ones
/// (module docs).
pub struct HugePages;

/// A transparent huge page on x86-64 and aarch64 with 4 KiB pages.
const HUGE: usize = 2 << 20;

#[cfg(target_os = "linux")]
mod cache;

/// Blocks from this size on are the cache's (Linux; glibc's own threshold
/// for mapping a block is 128 KiB, rising with the blocks freed).
pub const LARGE_FROM: usize = 256 << 10;

/// The whole huge pages inside the block of `len` bytes at address `at`:
/// their start and length, or `None` for none.
pub fn inside(at: usize, len: usize) -> Option<(usize, usize)> {
    let start = at.checked_next_multiple_of(HUGE)?;
    let end = at.checked_add(len)? & !(HUGE - 1);
    (end > start).then(|| (start, end - start))
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

/// Whether a block of `layout` is the cache's ([`cache`], Linux), and
/// its length in whole pages.
#[cfg(target_os = "linux")]
fn large(layout: Layout) -> Option<usize> {
    if layout.size() < LARGE_FROM || layout.align() > cache::PAGE || !cache::page_size_ok() {
        return None;
    }
    cache::pages(layout.size())
}

/// No cache off Linux.
#[cfg(not(target_os = "linux"))]
fn large(_: Layout) -> Option<usize> {
    None
}

// SAFETY: a large block ([`large`]) is the cache's from its allocation to
// its release (the layout a block is freed or grown with is the one it was
// allocated with, the caller's contract, so `large` gives the same answer
// each time); every other call is forwarded to `System` with the caller's
// arguments.
unsafe impl GlobalAlloc for HugePages {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        match large(layout) {
            Some(len) => cache_alloc(len, false),
            // SAFETY: the caller's contract, forwarded.
            None => unsafe { System.alloc(layout) },
        }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        match large(layout) {
            Some(len) => cache_alloc(len, true),
            // SAFETY: the caller's contract, forwarded.
            None => unsafe { System.alloc_zeroed(layout) },
        }
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        match large(layout) {
            Some(len) => cache_dealloc(p, len),
            // SAFETY: the caller's contract, forwarded.
            None => unsafe { System.dealloc(p, layout) },
        }
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, size: usize) -> *mut u8 {
        // SAFETY: the caller's contract: `size`, rounded up to the
        // alignment, does not overflow `isize`.
        let new = unsafe { Layout::from_size_align_unchecked(size, layout.align()) };
        match (large(layout), large(new)) {
            (Some(old), Some(len)) => cache_realloc(p, old, len),
            // SAFETY: the caller's contract, forwarded.
            (None, None) => unsafe { System.realloc(p, layout, size) },
            _ => {
                // one side the cache's: a new block, the contents copied
                // SAFETY: `new` is a valid non-zero layout (above).
                let q = unsafe { self.alloc(new) };
                if !q.is_null() {
                    // SAFETY: two distinct live blocks, each of at least
                    // the smaller size; the old one freed with its layout.
                    unsafe {
                        std::ptr::copy_nonoverlapping(p, q, layout.size().min(size));
                        self.dealloc(p, layout);
                    }
                }
                q
            }
        }
    }
}

#[cfg(target_os = "linux")]
use cache::{alloc as cache_alloc, dealloc as cache_dealloc, realloc as cache_realloc};

// never called off Linux (`large` is `None` there)
#[cfg(not(target_os = "linux"))]
fn cache_alloc(_: usize, _: bool) -> *mut u8 {
    std::ptr::null_mut()
}
#[cfg(not(target_os = "linux"))]
fn cache_dealloc(_: *mut u8, _: usize) {}
#[cfg(not(target_os = "linux"))]
fn cache_realloc(_: *mut u8, _: usize, _: usize) -> *mut u8 {
    std::ptr::null_mut()
}

#[cfg(test)]
mod tests;
