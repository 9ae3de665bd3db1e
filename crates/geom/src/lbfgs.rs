//! Limited-memory BFGS (Nocedal & Wright, *Numerical Optimization*,
//! algorithm 7.4) with a backtracking Armijo line search.
//!
//! Input: a start point and a function returning the value and writing
//! the gradient. Output: the point after at most `max_iter` iterations,
//! stopped early when the largest gradient entry is below `gtol` or no
//! step decreases the value. Invariant: the value never increases.

/// History length.
const M: usize = 8;

/// Minimises `f` from `x` (in place); returns the iterations made.
/// `first_step`: the largest entry of the first step (later steps are
/// scaled by the curvature seen); `max_step`: the largest entry of any
/// step (a longer one is shortened before the line search, which would
/// otherwise halve it many times where the curvature changes fast);
/// `done`: asked after each step, whose point `f` saw last; `true` stops
/// there (the caller's goal is reached before the minimum).
pub fn minimize(
    x: &mut [f64],
    mut f: impl FnMut(&[f64], &mut [f64]) -> f64,
    max_iter: usize,
    gtol: f64,
    first_step: f64,
    max_step: f64,
    mut done: impl FnMut() -> bool,
) -> usize {
    let n = x.len();
    if n == 0 {
        return 0;
    }
    let mut g = vec![0.0; n];
    let mut fx = f(x, &mut g);
    let (mut s_hist, mut y_hist): (Vec<Vec<f64>>, Vec<Vec<f64>>) = (Vec::new(), Vec::new());
    let mut rho: Vec<f64> = Vec::new();
    let (mut xn, mut gn, mut d) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let inf_norm = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut t_last = 1.0f64;
    for it in 0..max_iter {
        if !fx.is_finite() || inf_norm(&g) < gtol {
            return it;
        }
        // d = −H g by the two-loop recursion
        d.copy_from_slice(&g);
        let mut alpha = vec![0.0; s_hist.len()];
        for i in (0..s_hist.len()).rev() {
            alpha[i] = rho[i] * dotv(&s_hist[i], &d);
            axpy(&mut d, -alpha[i], &y_hist[i]);
        }
        if let (Some(s), Some(y)) = (s_hist.last(), y_hist.last()) {
            let gamma = dotv(s, y) / dotv(y, y);
            d.iter_mut().for_each(|v| *v *= gamma);
        } else {
            let scale = first_step / inf_norm(&g);
            d.iter_mut().for_each(|v| *v *= scale);
        }
        for i in 0..s_hist.len() {
            let beta = rho[i] * dotv(&y_hist[i], &d);
            axpy(&mut d, alpha[i] - beta, &s_hist[i]);
        }
        d.iter_mut().for_each(|v| *v = -*v);
        let mut slope = dotv(&g, &d);
        if slope >= 0.0 {
            // not a descent direction: restart along −g
            let scale = first_step / inf_norm(&g);
            for (di, gi) in d.iter_mut().zip(&g) {
                *di = -gi * scale;
            }
            slope = dotv(&g, &d);
            s_hist.clear();
            y_hist.clear();
            rho.clear();
        }
        let longest = inf_norm(&d);
        if longest > max_step {
            let k = max_step / longest;
            d.iter_mut().for_each(|v| *v *= k);
            slope *= k;
        }
        // backtracking line search (Armijo)
        // from twice the last accepted step: where the curvature changes
        // fast the steps stay short, and each would be halved as often
        let mut t = (2.0 * t_last).min(1.0);
        let mut accepted = None;
        for _ in 0..40 {
            for i in 0..n {
                xn[i] = x[i] + t * d[i];
            }
            let fnew = f(&xn, &mut gn);
            if fnew.is_finite() && fnew <= fx + 1e-4 * t * slope {
                accepted = Some(fnew);
                t_last = t;
                break;
            }
            t *= 0.5;
        }
        let Some(fnew) = accepted else {
            return it;
        };
        let s: Vec<f64> = (0..n).map(|i| xn[i] - x[i]).collect();
        let y: Vec<f64> = (0..n).map(|i| gn[i] - g[i]).collect();
        let sy = dotv(&s, &y);
        x.copy_from_slice(&xn);
        g.copy_from_slice(&gn);
        let decrease = fx - fnew;
        fx = fnew;
        if sy > 1e-16 * dotv(&y, &y).max(f64::MIN_POSITIVE) {
            if s_hist.len() == M {
                s_hist.remove(0);
                y_hist.remove(0);
                rho.remove(0);
            }
            rho.push(1.0 / sy);
            s_hist.push(s);
            y_hist.push(y);
        }
        if decrease <= 1e-14 * fx.abs() || done() {
            return it + 1;
        }
    }
    max_iter
}

fn dotv(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn axpy(y: &mut [f64], a: f64, x: &[f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += a * xi;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rosenbrock() {
        let mut x = vec![-1.2, 1.0];
        let it = minimize(
            &mut x,
            |x, g| {
                let (a, b) = (x[0], x[1]);
                g[0] = -2.0 * (1.0 - a) - 400.0 * a * (b - a * a);
                g[1] = 200.0 * (b - a * a);
                (1.0 - a).powi(2) + 100.0 * (b - a * a).powi(2)
            },
            500,
            1e-9,
            0.1,
            f64::INFINITY,
            || false,
        );
        assert!(
            (x[0] - 1.0).abs() < 1e-6 && (x[1] - 1.0).abs() < 1e-6,
            "{x:?} after {it}"
        );
    }
}
