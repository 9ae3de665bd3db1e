//! The advised range stays inside the block; blocks allocated, grown,
//! zeroed and freed through [`HugePages`] keep their contents.

use super::*;

#[test]
fn the_advised_range_is_whole_huge_pages_inside_the_block() {
    let cases = [
        (0, 0),
        (1, HUGE),
        (HUGE, HUGE),
        (HUGE - 1, 2 * HUGE + 2),
        (3 * HUGE + 5, 5 * HUGE),
        (usize::MAX - HUGE, HUGE),
        (12_345, 40 << 20),
    ];
    let mut some = 0;
    for (at, len) in cases {
        if let Some((start, n)) = inside(at, len) {
            some += 1;
            assert_eq!(start % HUGE, 0, "{at} {len}");
            assert_eq!(n % HUGE, 0, "{at} {len}");
            assert!(n > 0 && start >= at && start + n <= at + len, "{at} {len}");
            // no whole huge page of the block is left out
            assert!(
                start - at < HUGE && at + len - (start + n) < HUGE,
                "{at} {len}"
            );
        } else {
            // no whole huge page fits
            let first = at.checked_next_multiple_of(HUGE);
            assert!(first.is_none_or(|s| s.checked_add(HUGE).is_none_or(|e| e > at + len)));
        }
    }
    assert!(some >= 3, "{some}");
}

/// A vector of `n` values through the allocator, its values read back
/// after growing it and after a zeroed block beside it.
#[test]
fn blocks_keep_their_contents() {
    let a = HugePages;
    for n in [1usize, 1000, ADVISE_FROM / 8 - 3, ADVISE_FROM / 4 + 17] {
        let layout = Layout::array::<u64>(n).expect("layout");
        // SAFETY: a non-zero layout; every block is freed with its layout
        unsafe {
            let p = a.alloc(layout).cast::<u64>();
            assert!(!p.is_null());
            for i in 0..n {
                p.add(i).write(i as u64 * 7);
            }
            let z = a.alloc_zeroed(layout).cast::<u64>();
            assert!(!z.is_null());
            assert!((0..n).all(|i| z.add(i).read() == 0), "{n}");
            let grown = Layout::array::<u64>(3 * n).expect("layout");
            let q = a.realloc(p.cast(), layout, grown.size()).cast::<u64>();
            assert!(!q.is_null());
            assert!((0..n).all(|i| q.add(i).read() == i as u64 * 7), "{n}");
            a.dealloc(q.cast(), grown);
            a.dealloc(z.cast(), layout);
        }
    }
}
