//! Number text for TetGen's files, written without `core::fmt` (which
//! took ~60 % of the time of writing the `.poly`).
//!
//! Input: `f64` / `u64` values and a byte buffer (ASCII text) to append to. Output: the
//! value's text. Invariant: exact round trip — a float is written as a C99
//! hexadecimal float (`%a`: `-0x1.8p+3`), which `strtod` (TetGen's number
//! reader) converts back to the same bits, so TetGen sees exactly the
//! points it would see from the shortest decimal text. Non-finite values
//! are written as `nan` / `inf` (never produced by a valid slab).

/// Appends the decimal text of `x`.
pub fn push_uint(s: &mut Vec<u8>, mut x: u64) {
    let mut buf = [0u8; 20];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (x % 10) as u8;
        x /= 10;
        if x == 0 {
            break;
        }
    }
    s.extend_from_slice(&buf[i..]);
}

/// Appends the C99 hexadecimal text of `x` (module docs).
pub fn push_hex_float(s: &mut Vec<u8>, x: f64) {
    if x.is_nan() {
        s.extend_from_slice(b"nan");
        return;
    }
    if x.is_sign_negative() {
        s.push(b'-');
    }
    if x.is_infinite() {
        s.extend_from_slice(b"inf");
        return;
    }
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let mut mantissa = bits & ((1u64 << 52) - 1);
    let (lead, exp) = match (biased, mantissa) {
        (0, 0) => (b'0', 0),
        (0, _) => (b'0', -1022),
        _ => (b'1', biased - 1023),
    };
    s.extend_from_slice(&[b'0', b'x', lead]);
    if mantissa != 0 {
        s.push(b'.');
        let mut digits = 13;
        while mantissa & 0xf == 0 {
            mantissa >>= 4;
            digits -= 1;
        }
        for k in (0..digits).rev() {
            let d = ((mantissa >> (4 * k)) & 0xf) as u8;
            s.push(if d < 10 { b'0' + d } else { b'a' + d - 10 });
        }
    }
    s.push(b'p');
    s.push(if exp < 0 { b'-' } else { b'+' });
    push_uint(s, exp.unsigned_abs());
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hex(x: f64) -> String {
        let mut s = Vec::new();
        push_hex_float(&mut s, x);
        String::from_utf8(s).expect("ASCII")
    }

    /// Reads back what [`push_hex_float`] writes (the subset of `%a`).
    fn parse_hex(t: &str) -> f64 {
        let (neg, t) = t.strip_prefix('-').map_or((false, t), |r| (true, r));
        let t = t.strip_prefix("0x").expect("0x");
        let (m, e) = t.split_once('p').expect("p");
        let (lead, frac) = m.split_once('.').unwrap_or((m, ""));
        let mut v = lead.parse::<f64>().expect("lead");
        for (k, c) in frac.chars().enumerate() {
            let d = c.to_digit(16).expect("hex digit") as f64;
            v += d * 16f64.powi(-(k as i32) - 1);
        }
        let v = v * 2f64.powi(e.parse::<i32>().expect("exp"));
        if neg {
            -v
        } else {
            v
        }
    }

    #[test]
    fn integers() {
        for x in [0u64, 7, 10, 12345, u64::MAX] {
            let mut s = b"a".to_vec();
            push_uint(&mut s, x);
            assert_eq!(s, format!("a{x}").into_bytes());
        }
    }

    #[test]
    fn hex_floats_are_exact() {
        assert_eq!(hex(0.0), "0x0p+0");
        assert_eq!(hex(-0.0), "-0x0p+0");
        assert_eq!(hex(1.0), "0x1p+0");
        assert_eq!(hex(-12.0), "-0x1.8p+3");
        assert_eq!(hex(0.1), "0x1.999999999999ap-4");
        assert_eq!(hex(f64::MIN_POSITIVE / 4.0), "0x0.4p-1022");
        assert_eq!(hex(f64::INFINITY), "inf");
        let mut x = 0.123_456_789_f64;
        for _ in 0..200 {
            x = (x * 7.31 + 0.37).fract() * 10f64.powi((x * 40.0) as i32 - 20);
            for y in [x, -x, 1.0 / x] {
                assert_eq!(parse_hex(&hex(y)).to_bits(), y.to_bits(), "{y:e}");
            }
        }
    }
}
