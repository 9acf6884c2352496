//! Axis ticks and the numbers people read on figures, shared by the window and
//! the file writers so that both label an axis the same way.
//!
//! Logarithmic axes spanning two decades or more tick at powers of ten,
//! labelled 10ⁿ, with unlabelled minor ticks at 2–9 (or at the skipped
//! decades when labels must skip some). Shorter logarithmic spans tick at
//! 1, 2 and 5 times powers of ten, and spans under a factor of about eight
//! fall back to linear 1-2-5 steps. Linear axes tick at 1, 2 or 5 times a
//! power of ten. No label carries more than three significant digits for
//! ranges that are not narrower than a thousandth of their magnitude.

use super::Scale;

/// One tick mark: where it sits (in data units) and its label (none for a
/// minor tick).
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    /// Position in data units (not log10 of it).
    pub value: f64,
    /// Text below or beside the tick; `None` for an unlabelled minor tick.
    pub label: Option<String>,
}

impl Tick {
    fn major(value: f64, label: String) -> Self {
        Tick { value, label: Some(label) }
    }
    fn minor(value: f64) -> Self {
        Tick { value, label: None }
    }
    /// Whether the tick carries a label.
    pub fn is_major(&self) -> bool {
        self.label.is_some()
    }
}

/// Ticks for an axis showing `lo..=hi` (data units) with at most
/// `max_labels` labelled ticks. Returns ticks in increasing order; an empty
/// or non-finite range (or a non-positive one on a log axis) gives none.
pub fn ticks(lo: f64, hi: f64, scale: Scale, max_labels: usize) -> Vec<Tick> {
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    let max_labels = max_labels.max(2);
    if !lo.is_finite() || !hi.is_finite() {
        return Vec::new();
    }
    match scale {
        Scale::Linear => linear(lo, hi, max_labels),
        Scale::Log if lo > 0.0 => log(lo, hi, max_labels),
        Scale::Log => Vec::new(),
    }
}

/// Tolerance for "this value is on the axis" in relative terms.
const EDGE: f64 = 1e-9;

fn linear(lo: f64, hi: f64, max_labels: usize) -> Vec<Tick> {
    let span = hi - lo;
    if span <= 0.0 {
        return vec![Tick::major(lo, number(lo, 3))];
    }
    let raw = span / max_labels as f64;
    let p = 10f64.powf(raw.log10().floor());
    let (mut mantissa, mut step) = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|&m| (m, m * p))
        .find(|&(_, s)| s >= raw * (1.0 - EDGE))
        .unwrap_or((10.0, 10.0 * p));
    // At least two labels, so that the axis can be read: a step that leaves
    // one multiple inside the range gives way to the next smaller 1-2-5 step.
    let labelled = |step: f64| ((hi / step + EDGE).floor() - (lo / step - EDGE).ceil() + 1.0).max(0.0);
    while labelled(step) < 2.0 {
        (mantissa, step) = match mantissa {
            10.0 => (5.0, step / 2.0),
            5.0 => (2.0, step * 0.4),
            2.0 => (1.0, step / 2.0),
            _ => (5.0, step / 2.0),
        };
    }
    let minor = step / if mantissa == 2.0 { 4.0 } else { 5.0 };
    let decimals = decimals_for(step);
    let scientific = lo.abs().max(hi.abs()) >= 1e5 || (lo.abs().max(hi.abs()) < 1e-3);
    let mut out = Vec::new();
    let first = (lo / minor - EDGE).ceil() as i64;
    let last = (hi / minor + EDGE).floor() as i64;
    let per_major = (step / minor).round() as i64;
    for k in first..=last {
        let v = k as f64 * minor;
        if k.rem_euclid(per_major) == 0 {
            let v = if v.abs() < step * EDGE { 0.0 } else { v };
            let label = if scientific { number(v, sig_for(v, step)) } else { fixed(v, decimals) };
            out.push(Tick::major(v, label));
        } else {
            out.push(Tick::minor(v));
        }
    }
    out
}

fn log(lo: f64, hi: f64, max_labels: usize) -> Vec<Tick> {
    let (a, b) = (lo.log10(), hi.log10());
    let d0 = (a - EDGE).ceil() as i32;
    let d1 = (b + EDGE).floor() as i32;
    let decades = d1 - d0 + 1;
    if decades >= 3 || (decades >= 2 && b - a >= 1.5) {
        return log_decades(a, b, d0, d1, max_labels);
    }
    if b - a >= 0.9 {
        // About one decade: 1, 2, 5 times powers of ten, minors at the rest.
        let mut out = Vec::new();
        for d in (a.floor() as i32)..=(b.ceil() as i32) {
            for m in 1..=9 {
                let v = m as f64 * 10f64.powi(d);
                if v < lo * (1.0 - EDGE) || v > hi * (1.0 + EDGE) {
                    continue;
                }
                if matches!(m, 1 | 2 | 5) {
                    out.push(Tick::major(v, number(v, 1)));
                } else {
                    out.push(Tick::minor(v));
                }
            }
        }
        if out.iter().filter(|t| t.is_major()).count() <= max_labels {
            return out;
        }
        for t in &mut out {
            let m = (t.value / 10f64.powf(t.value.log10().floor())).round();
            if m != 1.0 {
                t.label = None;
            }
        }
        return out;
    }
    linear(lo, hi, max_labels)
}

fn log_decades(a: f64, b: f64, d0: i32, d1: i32, max_labels: usize) -> Vec<Tick> {
    let decades = (d1 - d0 + 1) as usize;
    let every =
        [1usize, 2, 3, 5, 10, 20, 50, 100].into_iter().find(|&k| decades.div_ceil(k) <= max_labels).unwrap_or(200)
            as i32;
    // Minor ticks at 2..9 while they stay apart; at skipped decades otherwise.
    let fine = every == 1 && (b - a) <= 10.0;
    let mut out = Vec::new();
    for d in (a.floor() as i32)..=(b.ceil() as i32) {
        let base = 10f64.powi(d);
        if d >= d0 && d <= d1 {
            if d.rem_euclid(every) == 0 {
                out.push(Tick::major(base, power_of_ten(d)));
            } else {
                out.push(Tick::minor(base));
            }
        }
        if fine {
            for m in 2..=9 {
                let v = m as f64 * base;
                let l = v.log10();
                if l >= a - EDGE && l <= b + EDGE {
                    out.push(Tick::minor(v));
                }
            }
        }
    }
    crate::sorting::sort_by_key(&mut out, |x| x.value);
    out
}

/// Decimals needed to tell apart multiples of `step` in fixed notation.
fn decimals_for(step: f64) -> usize {
    // Majors are 1, 2 or 5 × 10ᵏ, so one decimal per negative power suffices.
    let d = -(step.log10() + 1e-9).floor();
    d.max(0.0) as usize
}

/// Significant digits that tell `v` apart from its neighbours `step` away.
fn sig_for(v: f64, step: f64) -> usize {
    if v == 0.0 {
        return 1;
    }
    let digits = v.abs().log10().floor() - step.log10().floor() + 1.0;
    digits.clamp(1.0, 6.0) as usize
}

fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    minus(if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s })
}

/// `n` as a power of ten: "10³", "10⁻¹²"; "1" and "10" for 10⁰ and 10¹.
pub fn power_of_ten(n: i32) -> String {
    match n {
        0 => "1".into(),
        1 => "10".into(),
        _ => format!("10{}", superscript(n)),
    }
}

/// An integer in superscript digits: −3 → "⁻³".
pub fn superscript(n: i32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if n < 0 {
        s.push('⁻');
    }
    for c in n.unsigned_abs().to_string().chars() {
        if let Some(d) = c.to_digit(10) {
            s.push(DIGITS[d as usize]);
        }
    }
    s
}

/// A number as people write it on a figure or in a legend: at most `sig`
/// significant digits (trailing zeros dropped), plain between 10⁻³ and 10⁵,
/// otherwise "1.5×10⁻⁷"; minus as "−".
pub fn number(v: f64, sig: usize) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if !v.is_finite() {
        return if v.is_nan() {
            "NaN".into()
        } else if v > 0.0 {
            "∞".into()
        } else {
            "−∞".into()
        };
    }
    let sig = sig.clamp(1, 17);
    // Round to `sig` digits first: 99 960 at 3 digits is 1.00×10⁵.
    let rounded: f64 = format!("{v:.prec$e}", prec = sig - 1).parse().unwrap_or(v);
    let a = rounded.abs();
    let exp = a.log10().floor() as i32;
    if (1e-3..1e5).contains(&a) {
        let decimals = (sig as i32 - 1 - exp).max(0) as usize;
        let s = format!("{rounded:.decimals$}");
        let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s };
        minus(s)
    } else {
        let mantissa = rounded / 10f64.powi(exp);
        let m = format!("{mantissa:.prec$}", prec = sig - 1);
        let m = if m.contains('.') { m.trim_end_matches('0').trim_end_matches('.').to_string() } else { m };
        if m == "1" {
            power_of_ten(exp)
        } else if m == "-1" {
            format!("−{}", power_of_ten(exp))
        } else {
            format!("{}×{}", minus(m), power_of_ten(exp))
        }
    }
}

fn minus(s: String) -> String {
    let s =
        if s.starts_with("-0") && s.trim_start_matches(['-', '0', '.']).is_empty() { s[1..].to_string() } else { s };
    s.replace('-', "−")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(t: &[Tick]) -> Vec<String> {
        t.iter().filter_map(|t| t.label.clone()).collect()
    }

    fn significant_digits(label: &str) -> usize {
        let mantissa = label.split('×').next().unwrap_or(label);
        if mantissa.starts_with("10") && label.contains(['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'])
        {
            return 1;
        }
        let digits: String = mantissa.chars().filter(|c| c.is_ascii_digit()).collect();
        let trimmed = digits.trim_start_matches('0');
        let trimmed = if mantissa.contains('.') { trimmed } else { trimmed.trim_end_matches('0') };
        trimmed.len().max(1)
    }

    #[test]
    fn log_axes_over_decades_are_labelled_with_powers_of_ten() {
        let t = ticks(1e-3, 1e5, Scale::Log, 10);
        assert_eq!(labels(&t), ["10⁻³", "10⁻²", "10⁻¹", "1", "10", "10²", "10³", "10⁴", "10⁵"]);
        // Minor ticks at 2..9 of each decade, unlabelled.
        let minors: Vec<f64> = t.iter().filter(|t| !t.is_major()).map(|t| t.value).collect();
        assert_eq!(minors.len(), 8 * 8);
        assert!(minors.iter().any(|&v| (v - 2e-3).abs() < 1e-12));
        assert!(minors.iter().any(|&v| (v - 9e4).abs() < 1e-6));
    }

    #[test]
    fn many_decades_skip_labels_but_keep_decade_ticks() {
        let t = ticks(1e-35, 1.0, Scale::Log, 8);
        let l = labels(&t);
        assert!(l.len() <= 8, "{l:?}");
        assert!(l.contains(&"10⁻³⁰".to_string()) && l.contains(&"1".to_string()), "{l:?}");
        // Every decade still has a tick.
        assert_eq!(t.len(), 36);
    }

    #[test]
    fn window_labels_like_251_189_do_not_appear() {
        // The range that gave "251.189 / 199.526 / 158.489" in the window.
        for (lo, hi) in [(120.0, 300.0), (0.55, 0.9), (1e-9, 4e-8), (3.0, 2000.0), (0.07, 0.4)] {
            let t = ticks(lo, hi, Scale::Log, 6);
            let l = labels(&t);
            assert!(l.len() >= 2, "{lo}..{hi}: {l:?}");
            for s in &l {
                assert!(significant_digits(s) <= 3, "{lo}..{hi}: {s} in {l:?}");
            }
        }
    }

    #[test]
    fn sub_decade_spans_step_by_one_two_five() {
        let t = ticks(0.3, 2.5, Scale::Log, 8);
        assert_eq!(labels(&t), ["0.5", "1", "2"]);
        let t = ticks(120.0, 300.0, Scale::Log, 8);
        assert_eq!(labels(&t), ["150", "200", "250", "300"]);
        let t = ticks(0.0, 1.0, Scale::Linear, 6);
        assert_eq!(labels(&t), ["0", "0.2", "0.4", "0.6", "0.8", "1"]);
        let t = ticks(-7.0, 12.0, Scale::Linear, 5);
        assert_eq!(labels(&t), ["−5", "0", "5", "10"]);
    }

    #[test]
    fn linear_labels_of_large_and_small_numbers_use_powers_of_ten() {
        let t = ticks(0.0, 3e-9, Scale::Linear, 4);
        assert_eq!(labels(&t), ["0", "10⁻⁹", "2×10⁻⁹", "3×10⁻⁹"]);
        let t = ticks(0.0, 2.5e6, Scale::Linear, 6);
        assert_eq!(labels(&t), ["0", "5×10⁵", "10⁶", "1.5×10⁶", "2×10⁶", "2.5×10⁶"]);
    }

    #[test]
    fn labels_never_exceed_the_requested_count_and_ticks_are_ordered() {
        for &(lo, hi) in &[(1e-3, 1e5), (1.0, 1.1), (-3.3, 17.0), (1e-20, 1e20), (5.0, 50.0), (0.9, 1.0)] {
            for n in 2..12 {
                for scale in [Scale::Linear, Scale::Log] {
                    let t = ticks(lo, hi, scale, n);
                    let majors = t.iter().filter(|t| t.is_major()).count();
                    assert!(majors <= n + 1, "{lo}..{hi} {scale:?} n={n}: {majors}");
                    assert!(t.windows(2).all(|w| w[0].value < w[1].value), "{lo}..{hi} {scale:?}");
                    let tol = 1e-6 * lo.abs().max(hi.abs());
                    assert!(t.iter().all(|t| t.value >= lo - tol && t.value <= hi + tol));
                }
            }
        }
    }

    #[test]
    fn a_linear_axis_always_carries_at_least_two_labels() {
        for &(lo, hi) in &[(0.55, 1.02), (0.9, 1.0), (-0.26, 1.05), (7.1, 9.9), (1e-9, 1.7e-9), (999.0, 1001.0)] {
            for n in 2..6 {
                let t = ticks(lo, hi, Scale::Linear, n);
                let majors = t.iter().filter(|t| t.is_major()).count();
                assert!((2..=n + 1).contains(&majors), "{lo}..{hi} n={n}: {majors} labels");
            }
        }
    }

    #[test]
    fn bad_ranges_give_no_ticks() {
        assert!(ticks(f64::NAN, 1.0, Scale::Linear, 5).is_empty());
        assert!(ticks(-1.0, 1.0, Scale::Log, 5).is_empty());
        assert!(ticks(0.0, f64::INFINITY, Scale::Log, 5).is_empty());
        assert_eq!(ticks(2.0, 2.0, Scale::Linear, 5).len(), 1);
    }

    #[test]
    fn numbers_are_written_for_people() {
        assert_eq!(number(1000.018, 3), "1000");
        assert_eq!(number(215.477, 3), "215");
        assert_eq!(number(100.005, 3), "100");
        assert_eq!(number(0.0123456, 3), "0.0123");
        assert_eq!(number(1.5e-7, 3), "1.5×10⁻⁷");
        assert_eq!(number(1e-7, 3), "10⁻⁷");
        assert_eq!(number(-2.0e6, 3), "−2×10⁶");
        assert_eq!(number(99960.0, 3), "10⁵");
        assert_eq!(number(-0.5, 2), "−0.5");
        assert_eq!(superscript(-12), "⁻¹²");
        assert_eq!(power_of_ten(0), "1");
    }
}
