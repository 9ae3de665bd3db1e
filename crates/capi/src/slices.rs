//! Caller arrays as Rust slices, after the checks a C caller can get wrong.
//!
//! Input: a pointer to `n` items of `K` scalars each (positions: 3
//! doubles, triangles: 3 indices, tet parameters: 4·3 doubles, …) and the
//! argument's name for messages. Output: a slice of `n` items, or a
//! [`Failure`] naming the argument: null (unless `n` is 0), misaligned,
//! or `n` so large that the byte count overflows. What the pointer points
//! to cannot be checked: it must hold the stated number of values.

use crate::error::Failure;
use std::mem::size_of;

/// `n` items of type `E` (an array of `T`s) at `p`.
///
/// # Safety
/// `E` is an array type of `T` (`[T; K]` or nested), and unless `p` is null
/// it points to `n` readable, initialized items that outlive `'a` and are
/// not written meanwhile.
pub(crate) unsafe fn view<'a, T, E>(p: *const T, n: usize, what: &str) -> Result<&'a [E], Failure> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(Failure::argument(format!(
            "{what} is NULL but {n} items are expected"
        )));
    }
    let p = p.cast::<E>();
    if !p.is_aligned() {
        return Err(Failure::argument(format!("{what} is misaligned")));
    }
    let fits = n
        .checked_mul(size_of::<E>())
        .is_some_and(|bytes| bytes <= isize::MAX as usize);
    if !fits {
        return Err(Failure::argument(format!(
            "{what}: {n} items do not fit in memory"
        )));
    }
    // SAFETY: non-null, aligned, size checked; the caller vouches for the rest
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn null_misaligned_and_huge_arrays_are_named() {
        let v = [1.0f64, 2.0, 3.0, 4.0, 5.0, 6.0];
        // SAFETY: v holds two items of 3 doubles
        let s: &[[f64; 3]] = unsafe { view(v.as_ptr(), 2, "vpos") }
            .ok()
            .unwrap_or_default();
        assert_eq!(s, &[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        let msg = |r: Result<&[[f64; 3]], Failure>| r.err().map(|f| f.message).unwrap_or_default();
        // SAFETY: the checks fail before any read
        unsafe {
            assert_eq!(
                msg(view(std::ptr::null::<f64>(), 2, "vpos")),
                "vpos is NULL but 2 items are expected"
            );
            assert_eq!(
                msg(view(
                    v.as_ptr().cast::<u8>().add(1).cast::<f64>(),
                    1,
                    "vpos"
                )),
                "vpos is misaligned"
            );
            assert_eq!(
                msg(view(v.as_ptr(), usize::MAX / 8, "vpos")),
                format!("vpos: {} items do not fit in memory", usize::MAX / 8)
            );
            assert!(view::<f64, [f64; 3]>(std::ptr::null(), 0, "vpos").is_ok());
        }
    }
}
