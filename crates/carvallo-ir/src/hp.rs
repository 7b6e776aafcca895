//! High-precision reference evaluation with `astro-float`.
//!
//! [`eval`] runs a program with every operation carried out in binary floating point of
//! `precision_bits` bits (rounded half to even), starting from the exact values of the `f64`
//! parameters, inputs and constants. It is the independent path generated code and the `f64`
//! [`Interpreter`](crate::Interpreter) are checked against: at 256 bits its outputs are far more
//! accurate than anything computed in `f64`, unless the program is ill-conditioned.
//!
//! `atan2 y x` is built from `atan` with the quadrant corrections: for $x > 0$ it is
//! $\arctan(y/x)$, for $x < 0$ it is $\arctan(y/x) \pm \pi$ (plus when $y \ge 0$, minus when
//! $y < 0$), for $x = 0$ it is $\pm\pi/2$ by the sign of $y$, and $0$ when both are zero.
//! High-precision zeros are unsigned, so unlike `f64::atan2`, $\operatorname{atan2}(-0, x)$ is
//! $+\pi$ for $x < 0$. Negative integer powers are reciprocals of positive ones.
//! [`eval_f64`] rounds the results to the nearest `f64` (ties to even, subnormals included).

use astro_float::{BigFloat, Consts, RoundingMode};

use crate::{IrError, Op, Program, Value};

const RM: RoundingMode = RoundingMode::ToEven;

/// The smallest precision [`eval`] accepts (the `f64` significand width).
pub const MIN_PRECISION_BITS: usize = 53;
/// The largest precision [`eval`] accepts.
pub const MAX_PRECISION_BITS: usize = 1 << 20;

fn atan2(y: &BigFloat, x: &BigFloat, p: usize, cc: &mut Consts) -> BigFloat {
    if y.is_nan() || x.is_nan() {
        return y.add(x, p, RM);
    }
    if x.is_zero() {
        if y.is_zero() {
            return BigFloat::from_word(0, p);
        }
        let half_pi = cc.pi(p, RM).div(&BigFloat::from_word(2, p), p, RM);
        return if y.is_negative() { half_pi.neg() } else { half_pi };
    }
    let base = y.div(x, p, RM).atan(p, RM, cc);
    if x.is_negative() {
        let pi = cc.pi(p, RM);
        if y.is_negative() {
            base.sub(&pi, p, RM)
        } else {
            base.add(&pi, p, RM)
        }
    } else {
        base
    }
}

fn powi(a: &BigFloat, k: i32, p: usize) -> BigFloat {
    if k == 0 {
        return BigFloat::from_word(1, p);
    }
    let pos = a.powi(k.unsigned_abs() as usize, p, RM);
    if k < 0 {
        BigFloat::from_word(1, p).div(&pos, p, RM)
    } else {
        pos
    }
}

/// Evaluates `p` with `precision_bits`-bit arithmetic; one result per output.
///
/// Fails with [`IrError::Invalid`] if `p` does not validate or the precision is outside
/// [`MIN_PRECISION_BITS`]`..=`[`MAX_PRECISION_BITS`], and with [`IrError::ArgumentCount`] if
/// `params` or `inputs` do not have the program's lengths. Non-finite arguments and undefined
/// operations (such as the square root of a negative number) give NaN or infinite results, not
/// errors.
///
/// ```
/// use carvallo_ir::{hp, Program};
/// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet s = sqrt x\noutput y = s\n")?;
/// let y = hp::eval(&p, &[], &[2.0], 256)?;
/// let digits = format!("{}", y[0]);
/// assert!(digits.starts_with("1.41421356237309504880168872420969807856967187537694"), "{digits}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn eval(
    p: &Program,
    params: &[f64],
    inputs: &[f64],
    precision_bits: usize,
) -> Result<Vec<BigFloat>, IrError> {
    let prec = precision_bits;
    let params: Vec<BigFloat> = params.iter().map(|&x| from_f64(x, prec)).collect();
    let inputs: Vec<BigFloat> = inputs.iter().map(|&x| from_f64(x, prec)).collect();
    eval_big(p, &params, &inputs, prec)
}

/// Like [`eval`], with parameters and inputs given in high precision (for finite differences
/// and Newton steps finer than an `f64` can hold).
pub fn eval_big(
    p: &Program,
    params: &[BigFloat],
    inputs: &[BigFloat],
    precision_bits: usize,
) -> Result<Vec<BigFloat>, IrError> {
    p.validate()?;
    if !(MIN_PRECISION_BITS..=MAX_PRECISION_BITS).contains(&precision_bits) {
        return Err(IrError::invalid(format!(
            "precision {precision_bits} bits outside {MIN_PRECISION_BITS}..={MAX_PRECISION_BITS}"
        )));
    }
    for (what, expected, got) in
        [("parameters", p.params.len(), params.len()), ("inputs", p.inputs.len(), inputs.len())]
    {
        if expected != got {
            return Err(IrError::ArgumentCount { what, expected, got });
        }
    }
    let prec = precision_bits;
    let mut cc = Consts::new()
        .map_err(|e| IrError::invalid(format!("cannot set up astro-float constants: {e:?}")))?;
    let from = |x: f64| from_f64(x, prec);
    let mut vals: Vec<BigFloat> = Vec::with_capacity(p.insts.len());
    for inst in &p.insts {
        let get = |v: Value| -> &BigFloat {
            match v {
                Value::Param(i) => &params[i as usize],
                Value::Input(i) => &inputs[i as usize],
                Value::Inst(i) => &vals[i as usize],
            }
        };
        let r = match inst.op {
            Op::Const(c) => from(c),
            Op::Neg(a) => get(a).neg(),
            Op::Add(a, b) => get(a).add(get(b), prec, RM),
            Op::Sub(a, b) => get(a).sub(get(b), prec, RM),
            Op::Mul(a, b) => get(a).mul(get(b), prec, RM),
            Op::Div(a, b) => get(a).div(get(b), prec, RM),
            Op::Powi(a, k) => powi(get(a), k, prec),
            Op::Sqrt(a) => get(a).sqrt(prec, RM),
            Op::Sin(a) => get(a).sin(prec, RM, &mut cc),
            Op::Cos(a) => get(a).cos(prec, RM, &mut cc),
            Op::Tan(a) => get(a).tan(prec, RM, &mut cc),
            Op::Atan2(y, x) => atan2(get(y), get(x), prec, &mut cc),
        };
        vals.push(r);
    }
    Ok(p.outputs
        .iter()
        .map(|o| match o.value {
            Value::Param(i) => params[i as usize].clone(),
            Value::Input(i) => inputs[i as usize].clone(),
            Value::Inst(i) => vals[i as usize].clone(),
        })
        .collect())
}

/// Like [`eval`], with every result rounded to the nearest `f64`.
///
/// ```
/// use carvallo_ir::{hp, Program};
/// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet s = sin x\noutput y = s\n")?;
/// assert_eq!(hp::eval_f64(&p, &[], &[1.0], 256)?, vec![0.8414709848078965]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn eval_f64(
    p: &Program,
    params: &[f64],
    inputs: &[f64],
    precision_bits: usize,
) -> Result<Vec<f64>, IrError> {
    Ok(eval(p, params, inputs, precision_bits)?.iter().map(to_f64).collect())
}

/// The partial derivatives of every output of `p` with respect to the input or parameter
/// `wrt`, by the central difference $(f(x + h) - f(x - h))/2h$ with $h = 2^{-100}|x|$ (or
/// $2^{-100}$ at zero) evaluated with `precision_bits`-bit arithmetic from the exact `f64`
/// arguments, rounded to `f64`. At 256 bits the truncation error is about $h^2 \approx
/// 10^{-60}$ relative and the rounding error about $2^{-256}/h \approx 10^{-47}$: an
/// independent check of derivatives computed in `f64`, exact to the last bit for
/// well-conditioned programs.
///
/// Fails like [`eval`], and with [`IrError::Invalid`] when `wrt` is neither an input nor a
/// parameter.
///
/// ```
/// use carvallo_ir::{hp, Program};
/// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet s = sin x\noutput y = s\n")?;
/// assert_eq!(hp::derivative(&p, &[], &[1.0], "x", 256)?, vec![1.0f64.cos()]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn derivative(
    p: &Program,
    params: &[f64],
    inputs: &[f64],
    wrt: &str,
    precision_bits: usize,
) -> Result<Vec<f64>, IrError> {
    let prec = precision_bits;
    let mut bp: Vec<BigFloat> = params.iter().map(|&x| from_f64(x, prec)).collect();
    let mut bi: Vec<BigFloat> = inputs.iter().map(|&x| from_f64(x, prec)).collect();
    let slot: &mut BigFloat = if let Some(i) = p.inputs.iter().position(|n| n == wrt) {
        bi.get_mut(i)
    } else if let Some(i) = p.params.iter().position(|n| n == wrt) {
        bp.get_mut(i)
    } else {
        None
    }
    .ok_or_else(|| {
        IrError::invalid(format!("{wrt:?} is neither an input nor a parameter of {:?}", p.model))
    })?;
    let x = slot.clone();
    let scale = if x.is_zero() { from_f64(1.0, prec) } else { x.abs() };
    let h = scale.mul(&from_f64(pow2(-100), prec), prec, RM);
    *slot = x.add(&h, prec, RM);
    let plus = |bp: &[BigFloat], bi: &[BigFloat]| eval_big(p, bp, bi, prec);
    let fp = plus(&bp, &bi)?;
    let slot = if let Some(i) = p.inputs.iter().position(|n| n == wrt) {
        &mut bi[i]
    } else {
        let i = p.params.iter().position(|n| n == wrt).unwrap_or(0);
        &mut bp[i]
    };
    *slot = x.sub(&h, prec, RM);
    let fm = eval_big(p, &bp, &bi, prec)?;
    let two_h = h.add(&h, prec, RM);
    Ok(fp.iter().zip(&fm).map(|(a, b)| to_f64(&a.sub(b, prec, RM).div(&two_h, prec, RM))).collect())
}

/// The exact value of `x` with precision `p`.
///
/// `BigFloat::from_f64` (astro-float 0.9) halves subnormal numbers, so these are scaled into the
/// normal range first and scaled back exactly.
pub fn from_f64(x: f64, p: usize) -> BigFloat {
    if x != 0.0 && x.abs() < f64::MIN_POSITIVE {
        let scale = pow2(64);
        BigFloat::from_f64(x * scale, p).div(&BigFloat::from_f64(scale, p), p, RM)
    } else {
        BigFloat::from_f64(x, p)
    }
}

/// $2^k$ for $-1074 \le k \le 1023$, exactly.
fn pow2(k: i64) -> f64 {
    debug_assert!((-1074..=1023).contains(&k));
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (k + 1074))
    }
}

/// Rounds `x` to the nearest `f64`, ties to even (NaN and infinities map to themselves,
/// overflow gives an infinity, underflow a subnormal or a signed zero).
pub fn to_f64(x: &BigFloat) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x.is_inf_pos() {
        return f64::INFINITY;
    }
    if x.is_inf_neg() {
        return f64::NEG_INFINITY;
    }
    let sign = if x.is_negative() { -1.0 } else { 1.0 };
    let Some((words, _, _, e, _)) = x.as_raw_parts() else {
        return f64::NAN;
    };
    // The top 128 bits of the significand, and whether anything below them is non-zero.
    let n = words.len();
    let word = |i: usize| -> u128 { u128::from(words[i]) };
    let bits = astro_float::WORD_BIT_SIZE;
    let (mut m, sticky) = match (n, bits) {
        (0, _) => (0u128, false),
        (1, _) => (word(0) << (128 - bits), false),
        (_, 64) => (word(n - 1) << 64 | word(n - 2), words[..n - 2].iter().any(|&w| w != 0)),
        _ => {
            // 32-bit words: gather the top four.
            let mut m = 0u128;
            for k in 0..4.min(n) {
                m |= word(n - 1 - k) << (96 - 32 * k);
            }
            (m, words[..n.saturating_sub(4)].iter().any(|&w| w != 0))
        }
    };
    if m == 0 {
        return 0.0 * sign;
    }
    // Value = m / 2^128 * 2^e with m normalised to [2^127, 2^128).
    let lz = m.leading_zeros();
    m <<= lz;
    let e = i64::from(e) - i64::from(lz);
    if e > 1024 {
        return f64::INFINITY * sign;
    }
    let ulp = (e - 53).max(-1074);
    let shift = ulp - (e - 128); // bits of m below the last kept one, at least 75
    if shift > 128 {
        return 0.0 * sign;
    }
    let (q, rem, half) = if shift == 128 {
        (0u128, m, 1u128 << 127)
    } else {
        (m >> shift, m & ((1u128 << shift) - 1), 1u128 << (shift - 1))
    };
    let round_up = rem > half || (rem == half && (sticky || q & 1 == 1));
    let q = q + u128::from(round_up);
    // q <= 2^53 is exact in f64 and 2^ulp is a power of two: the product is exact or overflows.
    (q as f64) * pow2(ulp) * sign
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pow2_is_exact_over_the_whole_range() {
        assert_eq!(pow2(0), 1.0);
        assert_eq!(pow2(-1074), 5e-324);
        assert_eq!(pow2(-1022), f64::MIN_POSITIVE);
        assert_eq!(pow2(1023), 2f64.powi(1023));
        assert_eq!(pow2(-1023), f64::MIN_POSITIVE / 2.0);
    }

    #[test]
    fn from_f64_and_to_f64_round_trip() {
        for x in [0.0, 1.0, -2.5, 5e-324, -1e-310, f64::MAX, f64::MIN_POSITIVE, 0.1] {
            assert_eq!(to_f64(&from_f64(x, 128)).to_bits(), x.to_bits(), "{x:e}");
        }
        assert!(to_f64(&BigFloat::nan(None)).is_nan());
        let huge = from_f64(f64::MAX, 128).mul(&from_f64(2.0, 128), 128, RM);
        assert_eq!(to_f64(&huge), f64::INFINITY);
        // Half the smallest subnormal is a tie and rounds to even (zero); a bit more rounds up.
        let half = from_f64(5e-324, 128).div(&from_f64(2.0, 128), 128, RM);
        assert_eq!(to_f64(&half), 0.0);
        let more = half.mul(&from_f64(1.0000001, 128), 128, RM);
        assert_eq!(to_f64(&more), 5e-324);
    }

    #[test]
    fn non_finite_arguments_propagate() {
        let p = Program::parse(
            "carvallo-ir 1\nmodel m\ninput x\ninput z\nlet a = atan2 x z\nlet b = sin x\n\
             let c = powi z -2\nlet d = add x z\noutput a = a\noutput b = b\noutput c = c\n\
             output d = d\n",
        )
        .unwrap();
        let r = eval_f64(&p, &[], &[f64::NAN, 1.0], 128).unwrap();
        assert!(r[0].is_nan() && r[1].is_nan() && r[3].is_nan());
        assert_eq!(r[2], 1.0);
        let r = eval_f64(&p, &[], &[1.0, f64::INFINITY], 128).unwrap();
        assert_eq!(r[2], 0.0);
        assert_eq!(r[3], f64::INFINITY);
    }
}
