//! The number format shared by every renderer and by the normalisation of the snapshots:
//! significant digits without trailing zeros. It sits below [`super::text`] and
//! [`super::normalise`], which both use it.

/// Formats `x` with `digits` significant digits, without trailing zeros: plain decimal for
/// magnitudes in $[10^{-4}, 10^{\min(6, \text{digits})})$, scientific otherwise.
pub fn format_significant(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.max(1);
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((sci.as_str(), "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if exponent >= -4 && exponent < (digits as i32).min(6) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        trim_zeros(&format!("{:.*}", decimals, x))
    } else {
        format!("{}e{}", trim_zeros(mantissa), exponent)
    }
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}
