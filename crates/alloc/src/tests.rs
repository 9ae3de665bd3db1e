//! The advised range stays inside the block; blocks allocated, grown,
//! shrunk, zeroed and freed through [`HugePages`] keep their contents;
//! the cache of large blocks reuses them and keeps its peak invariant,
//! and packs fresh blocks in its arenas.

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
/// after growing it, shrinking it and after a zeroed block beside it; sizes
/// on both sides of the cache's threshold, so that blocks cross it when
/// they grow or shrink. Then the cache's own rules, on the global cache
/// (one test: the cache is the process's, tests run in parallel).
#[test]
fn blocks_keep_their_contents_and_the_cache_its_rules() {
    let a = HugePages;
    let large = LARGE_FROM / 8;
    for n in [1usize, 1000, large / 3, large - 1, large, 3 * large + 17] {
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
            z.write_bytes(0xab, n);
            a.dealloc(z.cast(), layout);
            // the block just freed, its bytes dirty, handed out zeroed
            let z = a.alloc_zeroed(layout).cast::<u64>();
            assert!((0..n).all(|i| z.add(i).read() == 0), "{n}");
            let grown = Layout::array::<u64>(3 * n).expect("layout");
            let q = a.realloc(p.cast(), layout, grown.size()).cast::<u64>();
            assert!(!q.is_null());
            assert!((0..n).all(|i| q.add(i).read() == i as u64 * 7), "{n}");
            let m = n / 2 + 1;
            let r = a.realloc(q.cast(), grown, m * 8).cast::<u64>();
            assert!((0..m).all(|i| r.add(i).read() == i as u64 * 7), "{n}");
            a.dealloc(r.cast(), Layout::array::<u64>(m).expect("layout"));
            a.dealloc(z.cast(), layout);
        }
    }
    #[cfg(target_os = "linux")]
    cache_rules(&a);
}

/// A freed, touched block is handed out again; one never touched is too,
/// but the other free ranges are unmapped first (the peak invariant); a
/// block that no free range holds is mapped fresh, after every free range
/// is unmapped.
#[cfg(target_os = "linux")]
fn cache_rules(a: &HugePages) {
    let layout = Layout::from_size_align(8 * LARGE_FROM, 8).expect("layout");
    let small = Layout::from_size_align(LARGE_FROM, 8).expect("layout");
    // SAFETY: non-zero layouts; every block is freed with its layout
    unsafe {
        let p = a.alloc(layout);
        p.write_bytes(1, layout.size());
        let s = a.alloc(small);
        s.write_bytes(1, small.size());
        a.dealloc(s, small);
        a.dealloc(p, layout);
        // (packed in one arena, the two may have merged into one range)
        assert!(cache::free_now().1 >= layout.size() + small.size());
        // touched: reused in place, the other range kept
        let q = a.alloc(layout);
        assert_eq!(q, p);
        assert!(cache::free_now().0 >= 1);
        a.dealloc(q, layout);
        // never touched: reused, every other free range unmapped
        let big = Layout::from_size_align(64 * LARGE_FROM, 8).expect("layout");
        let u = a.alloc(big);
        a.dealloc(u, big);
        let v = a.alloc(big);
        assert_eq!(v, u);
        assert_eq!(cache::free_now(), (0, 0));
        a.dealloc(v, big);
        // larger than any free range: fresh, after unmapping them all
        let huge = Layout::from_size_align(128 * LARGE_FROM, 8).expect("layout");
        let w = a.alloc(huge);
        assert!(!w.is_null());
        assert_eq!(cache::free_now(), (0, 0));
        a.dealloc(w, huge);
        arena_rules(a);
    }
}

/// Fresh blocks are the arena's next pages, packed; the last one grows in
/// place; one that cannot grow there moves, its contents kept.
#[cfg(target_os = "linux")]
fn arena_rules(a: &HugePages) {
    const MIB: usize = 1 << 20;
    let block = |n: usize| Layout::from_size_align(n * MIB, 8).expect("layout");
    // SAFETY: non-zero layouts; every block is freed with its layout
    unsafe {
        // larger than every free range and than an arena's rest: fresh,
        // at the start of a new arena of 64 MiB
        let x = a.alloc(block(40));
        assert!(!x.is_null());
        assert_eq!(x as usize % (2 * MIB), 0);
        assert_eq!(cache::free_now(), (0, 0));
        let y = a.alloc_zeroed(block(1));
        assert_eq!(y as usize, x as usize + 40 * MIB);
        assert!((0..MIB).all(|i| y.add(i).read() == 0));
        y.write_bytes(7, MIB);
        let g = a.realloc(y, block(1), 4 * MIB);
        assert_eq!(g, y);
        assert!((0..MIB).all(|i| g.add(i).read() == 7));
        g.add(MIB).write_bytes(9, 3 * MIB);
        // past the arena's end: moved
        let m = a.realloc(g, block(4), 30 * MIB);
        assert!(!m.is_null() && m != g);
        assert!((0..MIB).all(|i| m.add(i).read() == 7));
        assert!((MIB..4 * MIB).all(|i| m.add(i).read() == 9));
        a.dealloc(m, block(30));
        a.dealloc(x, block(40));
    }
}
