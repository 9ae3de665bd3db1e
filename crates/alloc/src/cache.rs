//! Large blocks (Linux): carved by the allocator itself from arenas it
//! maps, and when freed kept, to be handed out again, instead of given
//! back to the kernel.
//!
//! Why: a page the kernel hands out fresh is zeroed and faulted in on its
//! first touch, and on a virtual machine its host may have to back it too.
//! The extraction's stages each allocate their arrays anew: on torus537
//! about a third of the process's CPU time went to faults and zeroing
//! (BENCHMARKS.md, "Large blocks kept for the next stage"). A 4 KiB fault
//! costs here about three times what the same bytes cost in a 2 MiB
//! transparent huge page ("Large blocks from huge-page arenas").
//!
//! Input and output: blocks of at least [`crate::LARGE_FROM`] bytes whose
//! alignment is at most a page; the others are [`std::alloc::System`]'s
//! (the caller's choice, [`crate::HugePages`]). A block is a whole number
//! of pages, either fresh (the next pages of the current arena: arenas are
//! mapped 2 MiB aligned, at least [`ARENA_LEN`] long and advised as
//! transparent huge pages whole, so consecutive blocks share their huge
//! pages and no block's end is left to 4 KiB faults) or a piece of a free
//! range (the smallest that holds it; the rest stays free).
//!
//! Invariant, the peak: the free ranges are unmapped, all of them, before
//! any fresh memory is handed out. So the resident memory is at most the
//! live blocks plus the free ranges, and it grows only by fresh memory,
//! handed out when nothing is free: the process's peak is that of its
//! live blocks, as without the cache, up to the huge pages' granularity
//! (a huge page is resident whole once any of its bytes is touched; in an
//! arena the blocks are packed, so that is the blocks' untouched parts
//! and the arena's last huge page).

use std::sync::{Mutex, MutexGuard, PoisonError};

/// The page size assumed; blocks of a larger alignment are not the
/// cache's, and on a kernel of another page size there is no cache
/// ([`page_size_ok`]).
pub const PAGE: usize = 4096;

/// Whether the kernel's page size is [`PAGE`] (asked once; 1 yes, 2 no).
pub fn page_size_ok() -> bool {
    use std::sync::atomic::{AtomicU8, Ordering::Relaxed};
    static OK: AtomicU8 = AtomicU8::new(0);
    match OK.load(Relaxed) {
        1 => true,
        2 => false,
        _ => {
            // SAFETY: sysconf reads a constant of the process.
            let size = unsafe { libc::sysconf(libc::_SC_PAGESIZE) };
            let ok = usize::try_from(size) == Ok(PAGE);
            OK.store(if ok { 1 } else { 2 }, Relaxed);
            ok
        }
    }
}

/// A transparent huge page (x86-64 and aarch64 with 4 KiB pages).
const HUGE: usize = crate::HUGE;

/// Free ranges kept at most; a range freed when all are taken (after
/// merging with its neighbours) is unmapped.
const SLOTS: usize = 64;

/// The free ranges, `(address, length)`, none adjacent to another.
struct Free {
    ranges: [(usize, usize); SLOTS],
    n: usize,
}

static FREE: Mutex<Free> = Mutex::new(Free {
    ranges: [(0, 0); SLOTS],
    n: 0,
});

/// The free ranges, locked (a panic cannot leave them half-written: no
/// code that panics runs under the lock).
fn free() -> MutexGuard<'static, Free> {
    FREE.lock().unwrap_or_else(PoisonError::into_inner)
}

impl Free {
    /// `len` bytes from the smallest free range that holds them (its rest
    /// stays free), or `None`.
    fn take(&mut self, len: usize) -> Option<usize> {
        let best = (0..self.n)
            .filter(|&i| self.ranges[i].1 >= len)
            .min_by_key(|&i| self.ranges[i].1)?;
        let (at, n) = self.ranges[best];
        if n == len {
            self.remove(best);
        } else {
            self.ranges[best] = (at + len, n - len);
        }
        Some(at)
    }

    fn remove(&mut self, i: usize) {
        self.n -= 1;
        self.ranges[i] = self.ranges[self.n];
    }

    /// Keeps `[at, at + len)` free, merged with its free neighbours; the
    /// merged range back when no slot is left (the caller unmaps it).
    fn put(&mut self, mut at: usize, mut len: usize) -> Option<(usize, usize)> {
        let mut i = 0;
        while i < self.n {
            let (a, l) = self.ranges[i];
            if a + l == at || at + len == a {
                at = at.min(a);
                len += l;
                self.remove(i);
            } else {
                i += 1;
            }
        }
        if self.n == SLOTS {
            return Some((at, len));
        }
        self.ranges[self.n] = (at, len);
        self.n += 1;
        None
    }

    /// Every free range, taken out (for the caller to unmap, unlocked).
    fn drain(&mut self) -> ([(usize, usize); SLOTS], usize) {
        let out = (self.ranges, self.n);
        self.n = 0;
        out
    }
}

/// `size` rounded up to whole pages (`None` past the address space).
pub fn pages(size: usize) -> Option<usize> {
    size.checked_next_multiple_of(PAGE)
}

/// Unmaps every free range (before a fresh mapping: the peak invariant).
fn unmap_free() {
    let (ranges, n) = free().drain();
    for &(at, len) in &ranges[..n] {
        unmap(at, len);
    }
}

fn unmap(at: usize, len: usize) {
    // SAFETY: [at, at + len) is a range this module mapped and no block
    // holds any more.
    unsafe {
        libc::munmap(at as *mut libc::c_void, len);
    }
}

/// Fresh memory for a block of `len` bytes (whole pages), after the free
/// ranges are unmapped (the peak invariant): [`fresh`].
fn map_fresh(len: usize) -> *mut u8 {
    unmap_free();
    fresh(len)
}

/// The current arena's part never handed out, `[top, end)`: mapped, and
/// zero (never touched).
static ARENA: Mutex<(usize, usize)> = Mutex::new((0, 0));

/// Arenas are mapped at least this long (address space; only the pages
/// touched are backed).
pub const ARENA_LEN: usize = 64 << 20;

fn arena() -> MutexGuard<'static, (usize, usize)> {
    ARENA.lock().unwrap_or_else(PoisonError::into_inner)
}

/// `len` bytes (whole pages) never handed out: the current arena's next
/// pages, or the first of a new arena (the old one's rest unmapped); null
/// when the kernel refuses.
fn fresh(len: usize) -> *mut u8 {
    let mut a = arena();
    let (top, end) = *a;
    if end - top >= len {
        a.0 = top + len;
        return top as *mut u8;
    }
    let Some(size) = len.max(ARENA_LEN).checked_next_multiple_of(HUGE) else {
        return std::ptr::null_mut();
    };
    let p = map_huge(size);
    if p.is_null() {
        return p;
    }
    if end > top {
        unmap(top, end - top);
    }
    *a = (p as usize + len, p as usize + size);
    p
}

/// Grows the block `[p, p + old)` to `new` bytes in place when it ends
/// where the arena's fresh part begins and the arena has room.
fn grow_at_top(p: usize, old: usize, new: usize) -> bool {
    let mut a = arena();
    let ok = a.0 == p + old && a.1 - p >= new;
    if ok {
        a.0 = p + new;
    }
    ok
}

/// A fresh mapping of `len` bytes (a whole number of huge pages), 2 MiB
/// aligned and advised as huge pages; null when the kernel refuses.
fn map_huge(len: usize) -> *mut u8 {
    let Some(total) = len.checked_add(HUGE) else {
        return std::ptr::null_mut();
    };
    // SAFETY: a new private anonymous mapping; nothing else is touched.
    let p = unsafe {
        libc::mmap(
            std::ptr::null_mut(),
            total,
            libc::PROT_READ | libc::PROT_WRITE,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
            -1,
            0,
        )
    };
    if p == libc::MAP_FAILED {
        return std::ptr::null_mut();
    }
    let p = p as usize;
    let start = p.next_multiple_of(HUGE);
    // the ends beyond [start, start + len) given back
    if start > p {
        unmap(p, start - p);
    }
    unmap(start + len, p + total - (start + len));
    // whole huge pages from a huge page's start: advised whole
    debug_assert_eq!(len % HUGE, 0);
    crate::hint(start, len);
    start as *mut u8
}

/// Whether every page of `[at, at + len)` (whole pages) is resident
/// (`mincore`; `false` when it fails).
fn resident(at: usize, len: usize) -> bool {
    const STEP: usize = 4096;
    let mut flags = [0u8; STEP];
    let mut from = at;
    while from < at + len {
        let n = ((at + len - from) / PAGE).min(STEP);
        // SAFETY: [from, from + n pages) is mapped (a free range's piece)
        // and `flags` holds a byte per page.
        let r = unsafe { libc::mincore(from as *mut libc::c_void, n * PAGE, flags.as_mut_ptr()) };
        if r != 0 || flags[..n].iter().any(|&f| f & 1 == 0) {
            return false;
        }
        from += n * PAGE;
    }
    true
}

/// A block of `len` bytes (whole pages): a free range's piece, or fresh.
/// With `zeroed`, a reused piece is cleared (a fresh mapping is zero). A
/// piece not wholly resident (a block freed before all its pages were
/// touched) grows the resident memory when used: the other free ranges
/// are unmapped first, as before a fresh mapping (the peak invariant).
pub fn alloc(len: usize, zeroed: bool) -> *mut u8 {
    let reused = free().take(len);
    if let Some(at) = reused {
        if !resident(at, len) {
            unmap_free();
        }
    }
    match reused {
        Some(at) => {
            if zeroed {
                // SAFETY: [at, at + len) is mapped, writable, and now this
                // block's alone.
                unsafe { std::ptr::write_bytes(at as *mut u8, 0, len) };
            }
            at as *mut u8
        }
        None => map_fresh(len),
    }
}

/// Frees the block of `len` bytes (whole pages) at `p`: kept free.
pub fn dealloc(p: *mut u8, len: usize) {
    let full = free().put(p as usize, len);
    if let Some((at, n)) = full {
        unmap(at, n);
    }
}

/// The block at `p` of `old` bytes made `new` bytes (both whole pages),
/// its first `min(old, new)` bytes kept; null (the block left as it was)
/// when no memory is left.
pub fn realloc(p: *mut u8, old: usize, new: usize) -> *mut u8 {
    if new <= old {
        if new < old {
            dealloc(p.wrapping_add(new), old - new);
        }
        return p;
    }
    let reused = free().take(new);
    if let Some(at) = reused {
        if !resident(at, new) {
            unmap_free();
        }
        return moved(p, old, at as *mut u8);
    }
    if grow_at_top(p as usize, old, new) {
        unmap_free();
        return p;
    }
    // nothing free holds it: the pages moved by the kernel (no copy),
    // after the free ranges are unmapped (the peak invariant)
    unmap_free();
    // SAFETY: [p, p + old) is this block's mapping; the kernel moves or
    // grows it whole, or leaves it as it was.
    let q = unsafe { libc::mremap(p.cast(), old, new, libc::MREMAP_MAYMOVE) };
    if q != libc::MAP_FAILED {
        if let Some((at, n)) = crate::inside(q as usize, new) {
            crate::hint(at, n);
        }
        return q.cast();
    }
    // a block over two mappings (merged free ranges): copied
    moved(p, old, map_fresh(new))
}

/// The block at `p` of `old` bytes copied to `q` (unless null) and freed;
/// `q`.
fn moved(p: *mut u8, old: usize, q: *mut u8) -> *mut u8 {
    if !q.is_null() {
        // SAFETY: two distinct live blocks of at least `old` bytes.
        unsafe { std::ptr::copy_nonoverlapping(p, q, old) };
        dealloc(p, old);
    }
    q
}

/// How many ranges are free and their bytes (for the tests).
#[cfg(test)]
pub fn free_now() -> (usize, usize) {
    let f = free();
    (f.n, f.ranges[..f.n].iter().map(|r| r.1).sum())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn empty() -> Free {
        Free {
            ranges: [(0, 0); SLOTS],
            n: 0,
        }
    }

    /// Ranges merge with both neighbours; the smallest range that holds a
    /// block is cut, its rest kept; a range that finds no slot comes back.
    #[test]
    fn free_ranges_merge_split_and_overflow() {
        let mut f = empty();
        let p = PAGE;
        assert_eq!(f.put(10 * p, 2 * p), None);
        assert_eq!(f.put(14 * p, 2 * p), None);
        assert_eq!(f.put(12 * p, 2 * p), None);
        assert_eq!((f.n, f.ranges[0]), (1, (10 * p, 6 * p)));
        assert_eq!(f.put(100 * p, p), None);
        // the smallest that holds 1 page: the one of 1 page, taken whole
        assert_eq!(f.take(p), Some(100 * p));
        assert_eq!(f.take(2 * p), Some(10 * p));
        assert_eq!((f.n, f.ranges[0]), (1, (12 * p, 4 * p)));
        assert_eq!(f.take(5 * p), None);
        let mut f = empty();
        for i in 0..SLOTS {
            assert_eq!(f.put(4 * i * p, p), None);
        }
        // no slot: merged with its neighbour first, then given back
        assert_eq!(
            f.put(4 * SLOTS * p + 8 * p, p),
            Some((4 * SLOTS * p + 8 * p, p))
        );
        // merged with its neighbour, which frees that one's slot
        assert_eq!(f.put(p, p), None);
        assert!(f.ranges[..f.n].contains(&(0, 2 * p)));
        assert_eq!(f.drain().1, SLOTS);
        assert_eq!(f.n, 0);
    }
}
