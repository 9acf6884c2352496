//! Units on screen: every quantity in the unit the thesis uses for it.
//!
//! The model computes in SI (plus AU and yr where a scene says so). What a
//! reader sees follows the thesis: chapters 2 and 3 write SI with the
//! prefixes of a micrometre contact (nm, µm, ns, µN, J), chapters 4 to 6
//! write cgs and astronomical units (cm, g, erg, dyn, yr, AU). This module
//! converts a value and its SI unit to that display, writes units with
//! proper superscripts ("m s⁻¹"), and reads a typed value with a unit after
//! it ("5 um", "0.3 J/m^2", "2 mm") back into the unit of a field.
//!
//! It is a small table of the units the thesis uses rather than a general
//! units library: the crates that exist check units at compile time and do
//! not read unit text, and the thesis needs only these few symbols.

/// Exponents of metre, kilogram and second.
type Dim = [i8; 3];

/// Which system a scene's numbers are shown in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum System {
    /// SI with micrometre-scale prefixes (chapters 2 and 3).
    Si,
    /// cgs and astronomical units (chapters 4 to 6).
    Cgs,
}

/// A number and its unit, ready to show.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    /// The value in `unit`.
    pub value: f64,
    /// The unit, with superscripts; empty when dimensionless.
    pub unit: String,
}

impl Shown {
    /// "3.2 µm", "∞ m/s", "0.52" — three significant digits.
    pub fn text(&self) -> String {
        let n = crate::figure::human(self.value);
        if self.unit.is_empty() { n } else { format!("{n} {}", self.unit) }
    }
}

/// One unit symbol: its spellings, dimension and size in SI.
struct Symbol {
    names: &'static [&'static str],
    dim: Dim,
    si: f64,
}

const LENGTH: Dim = [1, 0, 0];
const MASS: Dim = [0, 1, 0];
const TIME: Dim = [0, 0, 1];
const ENERGY: Dim = [2, 1, -2];
const FORCE: Dim = [1, 1, -2];

/// The symbols a value may be typed or shown in.
const SYMBOLS: &[Symbol] = &[
    Symbol { names: &["nm"], dim: LENGTH, si: 1e-9 },
    Symbol { names: &["µm", "μm", "um", "micron"], dim: LENGTH, si: 1e-6 },
    Symbol { names: &["mm"], dim: LENGTH, si: 1e-3 },
    Symbol { names: &["cm"], dim: LENGTH, si: 1e-2 },
    Symbol { names: &["m"], dim: LENGTH, si: 1.0 },
    Symbol { names: &["km"], dim: LENGTH, si: 1e3 },
    Symbol { names: &["AU", "au"], dim: LENGTH, si: crate::physics::constants::AU },
    Symbol { names: &["g"], dim: MASS, si: 1e-3 },
    Symbol { names: &["kg"], dim: MASS, si: 1.0 },
    Symbol { names: &["ns"], dim: TIME, si: 1e-9 },
    Symbol { names: &["µs", "μs", "us"], dim: TIME, si: 1e-6 },
    Symbol { names: &["ms"], dim: TIME, si: 1e-3 },
    Symbol { names: &["s"], dim: TIME, si: 1.0 },
    Symbol { names: &["min"], dim: TIME, si: 60.0 },
    Symbol { names: &["h"], dim: TIME, si: 3600.0 },
    Symbol { names: &["yr"], dim: TIME, si: crate::physics::constants::YEAR },
    Symbol { names: &["kyr"], dim: TIME, si: 1e3 * crate::physics::constants::YEAR },
    Symbol { names: &["Myr"], dim: TIME, si: 1e6 * crate::physics::constants::YEAR },
    Symbol { names: &["J"], dim: ENERGY, si: 1.0 },
    Symbol { names: &["mJ"], dim: ENERGY, si: 1e-3 },
    Symbol { names: &["erg"], dim: ENERGY, si: 1e-7 },
    Symbol { names: &["N"], dim: FORCE, si: 1.0 },
    Symbol { names: &["mN"], dim: FORCE, si: 1e-3 },
    Symbol { names: &["µN", "μN", "uN"], dim: FORCE, si: 1e-6 },
    Symbol { names: &["nN"], dim: FORCE, si: 1e-9 },
    Symbol { names: &["dyn"], dim: FORCE, si: 1e-5 },
    Symbol { names: &["Pa"], dim: [-1, 1, -2], si: 1.0 },
    Symbol { names: &["kPa"], dim: [-1, 1, -2], si: 1e3 },
    Symbol { names: &["MPa"], dim: [-1, 1, -2], si: 1e6 },
    Symbol { names: &["GPa"], dim: [-1, 1, -2], si: 1e9 },
    Symbol { names: &["Hz"], dim: [0, 0, -1], si: 1.0 },
];

/// A unit read from text: its dimension and size in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Unit {
    dim: Dim,
    si: f64,
}

/// Normalises superscripts and the multiplication signs to ASCII.
fn ascii(unit: &str) -> String {
    let mut s = String::with_capacity(unit.len());
    for c in unit.chars() {
        match c {
            '⁻' => s.push_str("^-"),
            '¹' => s.push_str("^1"),
            '²' => s.push_str("^2"),
            '³' => s.push_str("^3"),
            '·' | '*' | '×' => s.push(' '),
            c => s.push(c),
        }
    }
    // "^-" followed by "^1" from "⁻¹" reads "^-^1".
    s.replace("^-^", "^-")
}

/// Reads a unit such as "m s^-1", "m/s", "J/m²", "g cm⁻³"; None if any
/// symbol is unknown. An empty text is dimensionless.
fn parse_unit(text: &str) -> Option<Unit> {
    let text = ascii(text.trim());
    let mut unit = Unit { dim: [0; 3], si: 1.0 };
    for (k, part) in text.split('/').enumerate() {
        let sign = if k == 0 { 1 } else { -1 };
        for factor in part.split_whitespace() {
            let (name, power) = match factor.split_once('^') {
                Some((n, p)) => (n, p.parse::<i8>().ok()?),
                None => {
                    // "m2", "cm3": a trailing digit is a power.
                    let digits = factor.trim_start_matches(|c: char| !c.is_ascii_digit() && c != '-');
                    if digits.is_empty() || digits.len() == factor.len() {
                        (factor, 1)
                    } else {
                        (&factor[..factor.len() - digits.len()], digits.parse::<i8>().ok()?)
                    }
                }
            };
            let sym = SYMBOLS.iter().find(|s| s.names.contains(&name))?;
            let p = power * sign;
            for (d, s) in unit.dim.iter_mut().zip(sym.dim) {
                *d += s * p;
            }
            unit.si *= sym.si.powi(i32::from(p));
        }
    }
    Some(unit)
}

/// A unit as the screen writes it: with superscripts, and one factor with a
/// negative power, written last, as a quotient — "m s^-1" → "m/s",
/// "g cm^-3" → "g/cm³", "J/m^2" → "J/m²", "s^-1" → "s⁻¹",
/// "kg m^-2 s^-1" → "kg m⁻² s⁻¹", "deg" → "°" (one form per unit, the
/// controls' own). Text it does not recognise is returned as it is.
pub fn pretty(unit: &str) -> String {
    if unit == "deg" {
        return "°".into();
    }
    let factors: Vec<&str> = unit.split(' ').collect();
    if let [head @ .., last] = &factors[..]
        && !head.is_empty()
        && !unit.contains('/')
        && head.iter().all(|f| !f.contains("^-"))
        && let Some((base, power)) = last.split_once("^-")
    {
        let power = if power == "1" { String::new() } else { format!("^{power}") };
        return superscripts(&format!("{}/{base}{power}", head.join(" ")));
    }
    superscripts(unit)
}

/// "^-12" → "⁻¹²", and the symbols of the Sun and the Earth.
pub(crate) fn superscripts(unit: &str) -> String {
    let unit = unit.replace("M_sun", "M☉").replace("L_sun", "L☉").replace("M_earth", "M⊕");
    let mut out = String::with_capacity(unit.len());
    let mut chars = unit.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '^' {
            out.push(c);
            continue;
        }
        while let Some(&d) = chars.peek() {
            let sup = match d {
                '-' => '⁻',
                '0' => '⁰',
                '1' => '¹',
                '2' => '²',
                '3' => '³',
                '4' => '⁴',
                '5' => '⁵',
                '6' => '⁶',
                '7' => '⁷',
                '8' => '⁸',
                '9' => '⁹',
                _ => break,
            };
            out.push(sup);
            chars.next();
        }
    }
    out
}

/// Picks the largest unit in which `v` (SI) reads at least 0.1 — "0.6 µm"
/// rather than "600 nm", as the thesis writes it — from a list of
/// (symbol, size in SI), smallest first.
fn by_magnitude(v: f64, choices: &[(&'static str, f64)]) -> (&'static str, f64) {
    let a = v.abs();
    let mut pick = choices[0];
    for &c in choices {
        if a >= c.1 * 0.09995 {
            pick = c;
        }
    }
    if a == 0.0 || !a.is_finite() {
        // Zero and infinity: the unit the quantity usually has.
        return choices[choices.len() / 2];
    }
    pick
}

/// A value in `si_unit` shown as the thesis shows it in `system`.
pub fn show(value: f64, si_unit: &str, system: System) -> Shown {
    let keep = || Shown { value, unit: pretty(si_unit) };
    let Some(unit) = parse_unit(si_unit) else { return keep() };
    if si_unit.trim().is_empty() || matches!(si_unit, "AU" | "yr") {
        return keep();
    }
    let si = value * unit.si;
    let (name, size): (&str, f64) = match (system, unit.dim) {
        (System::Si, LENGTH) => by_magnitude(si, &[("nm", 1e-9), ("µm", 1e-6), ("mm", 1e-3), ("m", 1.0), ("km", 1e3)]),
        (System::Cgs, LENGTH) => by_magnitude(
            si,
            &[("nm", 1e-9), ("µm", 1e-6), ("cm", 1e-2), ("km", 1e3), ("AU", crate::physics::constants::AU)],
        ),
        (System::Si, TIME) => by_magnitude(si, &[("ns", 1e-9), ("µs", 1e-6), ("ms", 1e-3), ("s", 1.0)]),
        (System::Cgs, TIME) => by_magnitude(si, &[("s", 1.0), ("yr", crate::physics::constants::YEAR)]),
        (System::Si, MASS) => ("kg", 1.0),
        (System::Cgs, MASS) => ("g", 1e-3),
        (System::Si, ENERGY) => ("J", 1.0),
        (System::Cgs, ENERGY) => ("erg", 1e-7),
        (System::Si, FORCE) => by_magnitude(si, &[("nN", 1e-9), ("µN", 1e-6), ("mN", 1e-3), ("N", 1.0)]),
        (System::Cgs, FORCE) => ("dyn", 1e-5),
        (System::Cgs, [-3, 1, 0]) => ("g/cm³", 1e3),
        (System::Cgs, [2, 0, -2]) => ("erg/g", 1e-4),
        (System::Cgs, [2, 1, -1]) => ("g cm²/s", 1e-7),
        _ => return keep(),
    };
    Shown { value: si / size, unit: name.to_string() }
}

/// `show(..).text()`.
pub fn text(value: f64, si_unit: &str, system: System) -> String {
    show(value, si_unit, system).text()
}

/// The system of a thesis chapter: SI up to chapter 3, cgs from chapter 4.
pub fn system_of_chapter(chapter: u8) -> System {
    if (4..=6).contains(&chapter) { System::Cgs } else { System::Si }
}

/// Writes a number as the window shows it ("1.5×10⁻⁷", "10⁻³", "−2") the
/// way Rust reads numbers ("1.5e-7", "1e-3", "-2"); other text is kept.
fn plain_number(text: &str) -> String {
    let sup = |c: char| match c {
        '⁻' => Some('-'),
        '⁰' => Some('0'),
        '¹' => Some('1'),
        '²' => Some('2'),
        '³' => Some('3'),
        '⁴' => Some('4'),
        '⁵' => Some('5'),
        '⁶' => Some('6'),
        '⁷' => Some('7'),
        '⁸' => Some('8'),
        '⁹' => Some('9'),
        _ => None,
    };
    let t = text.replace('−', "-");
    // "a×10ⁿ" or "10ⁿ" at the start: the exponent is the superscript run after "10".
    let (mantissa, rest) = match t.split_once("×10") {
        Some((m, rest)) => (m.to_string(), rest),
        None => match t.strip_prefix("10").or_else(|| t.strip_prefix("-10")) {
            Some(rest) if rest.starts_with(|c: char| sup(c).is_some()) => {
                ((if t.starts_with('-') { "-1" } else { "1" }).to_string(), rest)
            }
            _ => return t,
        },
    };
    let exponent: String = rest.chars().map_while(sup).collect();
    if exponent.is_empty() {
        return t;
    }
    let after: String = rest.chars().skip(exponent.chars().count()).collect();
    format!("{mantissa}e{exponent}{after}")
}

/// Reads a value typed into a field shown in `field_unit`, with or without a
/// unit after it: "5", "5 µm", "5um", "0.005 mm", "3 cm/s", "−2e-3". The
/// answer is in `field_unit`. A unit of another kind, or one this table does
/// not know, is refused with a message naming it.
pub fn parse_in(text: &str, field_unit: &str) -> Result<f64, String> {
    let t = plain_number(text.trim());
    // The number is the longest prefix that parses.
    let split = (0..=t.len())
        .rev()
        .filter(|&i| t.is_char_boundary(i))
        .find(|&i| t[..i].trim().parse::<f64>().is_ok())
        .ok_or_else(|| format!("\"{}\" is not a number", text.trim()))?;
    let number: f64 = t[..split].trim().parse().map_err(|_| format!("\"{}\" is not a number", text.trim()))?;
    let rest = t[split..].trim();
    if rest.is_empty() {
        return Ok(number);
    }
    let typed = parse_unit(rest).ok_or_else(|| format!("unknown unit \"{rest}\""))?;
    let field =
        parse_unit(field_unit).ok_or_else(|| format!("the field's unit \"{field_unit}\" cannot be converted"))?;
    if typed.dim != field.dim {
        let want = if field_unit.trim().is_empty() { "a pure number".to_string() } else { pretty(field_unit) };
        return Err(format!("\"{rest}\" is not a unit of the same kind as {want}"));
    }
    if typed.si == field.si {
        return Ok(number);
    }
    Ok(number * typed.si / field.si)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn superscripts() {
        assert_eq!(pretty("m s^-1"), "m/s");
        assert_eq!(pretty("J m^-2"), "J/m²");
        assert_eq!(pretty("g cm^-3"), "g/cm³");
        assert_eq!(pretty("m s^-2"), "m/s²");
        assert_eq!(pretty("J/m^2"), "J/m²");
        assert_eq!(pretty("s^-1"), "s⁻¹");
        assert_eq!(pretty("kg m^-2 s^-1"), "kg m⁻² s⁻¹");
        assert_eq!(pretty("m^2 s^-1"), "m²/s");
        assert_eq!(pretty("µm"), "µm");
        assert_eq!(pretty("deg"), "°");
        assert_eq!(pretty("M_sun"), "M☉");
        assert_eq!(pretty("M_earth yr^-1"), "M⊕/yr");
    }

    #[test]
    fn thesis_units_per_chapter() {
        assert_eq!(text(3.3e6, "kg", System::Cgs), "3.3×10⁹ g");
        assert_eq!(text(6.3e11, "s", System::Cgs), "20000 yr");
        assert_eq!(text(9800.0092 * crate::physics::constants::YEAR, "s", System::Cgs), "9800 yr");
        assert_eq!(text(2.5e-16, "J", System::Cgs), "2.5×10⁻⁹ erg");
        assert_eq!(text(2.5e-16, "J", System::Si), "2.5×10⁻¹⁶ J");
        assert_eq!(text(0.6e-6, "m", System::Si), "0.6 µm");
        assert_eq!(text(3e-9, "m", System::Si), "3 nm");
        assert_eq!(text(1.2e-8, "s", System::Si), "12 ns");
        assert_eq!(text(4.5e-6, "N", System::Si), "4.5 µN");
        assert_eq!(text(1.8e-10, "N", System::Cgs), "1.8×10⁻⁵ dyn");
        assert_eq!(text(f64::INFINITY, "m s^-1", System::Si), "∞ m/s");
        assert_eq!(text(0.05, "m", System::Cgs), "5 cm");
        assert_eq!(text(5.56e-10, "m", System::Cgs), "0.556 nm");
        assert_eq!(text(1000.0, "kg m^-3", System::Cgs), "1 g/cm³");
        assert_eq!(text(0.1, "J m^-2", System::Cgs), "0.1 J/m²");
        assert_eq!(text(30.0, "AU", System::Cgs), "30 AU");
        assert_eq!(text(0.52, "", System::Cgs), "0.52");
    }

    #[test]
    fn conversions_round_trip_through_si() {
        // Shown value times the shown unit's size is the SI value again.
        for (v, u) in [(3.3e6, "kg"), (6.3e11, "s"), (2.5e-16, "J"), (7e-7, "m"), (4.5e-6, "N"), (1e3, "kg m^-3")] {
            for sys in [System::Si, System::Cgs] {
                let s = show(v, u, sys);
                let back = parse_in(&format!("{:e} {}", s.value, s.unit), u).unwrap();
                assert!((back / v - 1.0).abs() < 1e-12, "{v} {u} → {s:?} → {back}");
            }
        }
    }

    #[test]
    fn typed_units() {
        assert_eq!(parse_in("5", "µm"), Ok(5.0));
        assert_eq!(parse_in("5 um", "µm"), Ok(5.0));
        assert_eq!(parse_in("5um", "µm"), Ok(5.0));
        assert!((parse_in("0.005 mm", "µm").unwrap() - 5.0).abs() < 1e-12);
        assert!((parse_in("300 cm/s", "m/s").unwrap() - 3.0).abs() < 1e-12);
        assert!((parse_in("3 m s^-1", "m/s").unwrap() - 3.0).abs() < 1e-12);
        assert!((parse_in("3 m s⁻¹", "m s^-1").unwrap() - 3.0).abs() < 1e-12);
        assert!((parse_in("100 mJ/m^2", "J/m²").unwrap() - 0.1).abs() < 1e-12);
        assert!((parse_in("−2e-3", "").unwrap() + 2e-3).abs() < 1e-18);
        assert!(parse_in("5 kg", "µm").unwrap_err().contains("not a unit of the same kind as µm"));
        assert!(parse_in("5 furlongs", "µm").unwrap_err().contains("unknown unit \"furlongs\""));
        assert!(parse_in("abc", "µm").unwrap_err().contains("not a number"));
        assert!(parse_in("5 m", "").is_err());
        // The window's own way of writing numbers reads back.
        assert_eq!(parse_in("1.5×10⁻⁷", ""), Ok(1.5e-7));
        assert_eq!(parse_in("10⁻³", ""), Ok(1e-3));
        assert_eq!(parse_in("−10⁴ m/s", "m/s"), Ok(-1e4));
        assert_eq!(parse_in("2×10³ µm", "µm"), Ok(2e3));
        assert_eq!(parse_in("100", ""), Ok(100.0));
    }
}
