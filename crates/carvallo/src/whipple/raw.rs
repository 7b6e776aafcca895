//! The benchmark parameters from raw measurements: BicycleParameters' `RawData/<name>Measured.txt`
//! (masses, geometry, the pendulum's orientations and the fitted pendulum periods) to the 26
//! parameters of Meijaard et al. (2007) with their uncertainties, as BicycleParameters'
//! `calculate_benchmark_from_measured` computes them (`Bicycle(name, pathToData,
//! forceRawCalc=True)`, Moore 2012, ch. 2).
//!
//! # The file
//! One `name = value` per line; a value `v+/-s` is a measured quantity of standard deviation
//! `s`, a plain `v` an exact number; several comma-separated values are averaged; lines starting
//! with `#` and the text after a `#` are skipped (`bicycleparameters.io.load_parameter_text_file`).
//!
//! # The computation
//! - wheel radii $r = d/(2\pi n)$ from the distance `d` rolled in `n` turns;
//! - the steer axis tilt $\lambda = \pi/180\,(90° - \gamma)$ from the head tube angle `gamma`, the
//!   wheelbase `w` and the fork offset `f` measured (when `w` is given), or from the offsets
//!   `h1`–`h5`, `d1`–`d4`, `d`: $a = h_1 + h_2 - h_3 + d_1/2 - d_2/2$,
//!   $b = h_4 - d_3/2 - h_5 + d_4/2$, $c = \sqrt{(d + (d_2 + d_3)/2)^2 - (a - b)^2}$,
//!   $\lambda$ the root of $\sin\lambda = (r_F - r_R + c\cos\lambda)/(a + b)$ and
//!   $w = (a + b)\cos\lambda + c\sin\lambda$, fork offset $b$;
//! - the trail $c = (r_F \sin\lambda - f)/\cos\lambda$;
//! - each frame hung at angles $\alpha_i$ from a point at distance $a_i$: the line
//!   $z = m x + b$ through its mass centre with $\beta = \lambda - \alpha\pi/180$, $m = -\tan\beta$,
//!   $b = -a/\cos\beta - r_R$ (rear frame), $b = -a/\cos\beta - r_F + w\tan\beta$ (front frame);
//!   the mass centre is the mean of the intersections of every ordered pair of lines;
//! - compound pendulum: $I = (T/2\pi)^2 m g l - m l^2$ for the wheels (`TcR1`, `TcF1` at `lR`,
//!   `lF`) and the frames (`TcB1`, `TcH1` about the axle, at their mass centres' distance);
//! - torsional pendulum: its stiffness $k = 4\pi^2 I_P/T_P^2$ from a rod of length `lP`, mass
//!   `mP`, diameter `dP` ($I_P = m_P(3 r^2 + l^2)/12$); then $I = k T^2/4\pi^2$ for the wheels'
//!   `IRxx`, `IFxx` and each frame orientation $J_i$; the frame's $I_{xx}, I_{xz}, I_{zz}$ solve
//!   $J_i = I_{xx}\cos^2\beta_i - 2 I_{xz}\sin\beta_i\cos\beta_i + I_{zz}\sin^2\beta_i$.
//!
//! # Uncertainties
//! Every measured quantity is an independent variable; each result carries its derivatives with
//! respect to all of them ([`carvallo_ir::dual`], exact to rounding) — the linear propagation
//! of the `uncertainties` package that BicycleParameters uses, correlations included
//! ([`Raw::covariance`]). One difference: for $\lambda$ from the offsets BicycleParameters keeps
//! the uncertainty of its initial guess $\operatorname{atan}(c/(a + b))$ (its source says "This
//! is not true!"); here $\lambda$'s derivatives come from the implicit function theorem on the
//! equation it solves.
//!
//! A front frame measured in two parts (fork `S`, handlebar `G`, the handlebar's reference
//! point from `h6`, `h7`, `d5`, `d6`, `l`) is combined into `H` by the parallel-axis theorem; a
//! frame hung in more than three orientations is solved by least squares; a flywheel `D`
//! measured inside the front wheel is returned beside the parameters ([`Raw::extra`]), not added
//! to them.

use carvallo_ir::dual::Dual;

use crate::whipple::parameter_text::{value_and_sigma, UncertainParams};
use crate::whipple::{WhippleParams, PARAM_NAMES};

/// The largest number of measured quantities with an uncertainty a file may have.
pub const MAX_MEASURED: usize = 96;

type D = Dual<MAX_MEASURED>;

const PI: f64 = std::f64::consts::PI;

/// Why raw measurements could not be turned into parameters.
#[derive(Clone, Debug, PartialEq)]
pub enum RawError {
    /// A line that is not `name = value[+/-sigma][, ...]`.
    Line {
        /// The 1-based line number.
        line: usize,
        /// The line (trimmed).
        text: String,
        /// What is wrong.
        reason: String,
    },
    /// A measurement the computation needs is missing.
    Missing {
        /// Its name.
        key: String,
    },
    /// Measurements this computation does not handle, or values that give no bicycle.
    Unsupported {
        /// The key at fault.
        key: String,
        /// Why.
        reason: String,
    },
}

impl std::fmt::Display for RawError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RawError::Line { line, text, reason } => write!(f, "line {line}: {reason} (`{text}`)"),
            RawError::Missing { key } => write!(f, "missing measurement {key}"),
            RawError::Unsupported { key, reason } => write!(f, "{key}: {reason}"),
        }
    }
}

impl std::error::Error for RawError {}

/// The nominal value of every measurement of a raw measurement file, `(name, value)` in the
/// order of the file (comma-separated values averaged, uncertainties dropped, as
/// BicycleParameters' `remove_uncertainties` does before seating a rider).
///
/// # Errors
/// [`RawError::Line`] for a line that is not `name = value[+/-sigma][, ...]`.
pub fn nominal_measurements(text: &str) -> Result<Vec<(String, f64)>, RawError> {
    let m = Measurements::read(text)?;
    Ok(m.entries.into_iter().map(|(n, d)| (n, d.value)).collect())
}

/// The benchmark parameters computed from raw measurements.
#[derive(Clone, Debug)]
pub struct Raw {
    /// The parameters and their standard deviations.
    pub params: UncertainParams,
    /// Quantities computed beside the model's 26 parameters, `(name, value, sigma)`: a flywheel's
    /// `mD`, `IDxx`, `IDyy` (not in the model; BicycleParameters' analysis ignores it too).
    pub extra: Vec<(String, f64, f64)>,
    /// The names of the measured quantities with an uncertainty, the variables of
    /// [`jacobian`](Self::jacobian), in the order of the file.
    pub measured: Vec<String>,
    /// Their standard deviations.
    pub measured_sigma: Vec<f64>,
    /// $\partial p_i/\partial x_j$: row $i$ in the order of [`PARAM_NAMES`], column $j$ in that
    /// of [`measured`](Self::measured).
    pub jacobian: Vec<Vec<f64>>,
}

impl Raw {
    /// The covariance matrix of the 26 parameters, $J \operatorname{diag}(\sigma^2) J^T$.
    pub fn covariance(&self) -> [[f64; 26]; 26] {
        std::array::from_fn(|i| {
            std::array::from_fn(|k| {
                (0..self.measured.len())
                    .map(|j| {
                        let s = self.measured_sigma[j];
                        self.jacobian[i][j] * self.jacobian[k][j] * s * s
                    })
                    .sum()
            })
        })
    }
}

/// The measurements of a file: each name with its value as a variable or a constant.
struct Measurements {
    entries: Vec<(String, D)>,
    names: Vec<String>,
    sigma: Vec<f64>,
}

impl Measurements {
    fn read(text: &str) -> Result<Measurements, RawError> {
        let mut m = Measurements { entries: Vec::new(), names: Vec::new(), sigma: Vec::new() };
        for (k, raw_line) in text.lines().enumerate() {
            if raw_line.starts_with('#') {
                continue;
            }
            let line = raw_line.trim().split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            let bad = |reason: String| RawError::Line {
                line: k + 1,
                text: raw_line.trim().to_string(),
                reason,
            };
            let (name, rest) =
                line.split_once('=').ok_or_else(|| bad("expected `name = value`".to_string()))?;
            let name = name.trim();
            if name.is_empty() {
                return Err(bad("no name before `=`".to_string()));
            }
            if m.entries.iter().any(|(n, _)| n == name) {
                return Err(bad(format!("measurement `{name}` given twice")));
            }
            let uncertain = rest.contains("+/-");
            let mut sum: Option<D> = None;
            let parts: Vec<&str> = rest.split(',').collect();
            for (j, part) in parts.iter().enumerate() {
                let (v, s) = value_and_sigma(part).map_err(|r| bad(format!("{name}: {r}")))?;
                let x = if uncertain {
                    if !part.contains("+/-") {
                        return Err(bad(format!(
                            "{name}: `{}` has no uncertainty beside values that have one",
                            part.trim()
                        )));
                    }
                    if m.names.len() == MAX_MEASURED {
                        return Err(bad(format!(
                            "more than {MAX_MEASURED} measurements with an uncertainty"
                        )));
                    }
                    m.names.push(if parts.len() == 1 {
                        name.to_string()
                    } else {
                        format!("{name}[{j}]")
                    });
                    m.sigma.push(s);
                    D::variable(v, m.names.len() - 1)
                } else {
                    D::constant(v)
                };
                sum = Some(match sum {
                    None => x,
                    Some(a) => a + x,
                });
            }
            let sum = sum.ok_or_else(|| bad(format!("{name}: no value")))?;
            let mean = if parts.len() == 1 { sum } else { sum / D::constant(parts.len() as f64) };
            m.entries.push((name.to_string(), mean));
        }
        Ok(m)
    }

    fn get(&self, key: &str) -> Option<D> {
        self.entries.iter().find(|(n, _)| n == key).map(|(_, v)| *v)
    }

    fn need(&self, key: &str) -> Result<D, RawError> {
        self.get(key).ok_or_else(|| RawError::Missing { key: key.to_string() })
    }

    fn has(&self, key: &str) -> bool {
        self.get(key).is_some()
    }
}

fn c(x: f64) -> D {
    D::constant(x)
}

fn sq(x: D) -> D {
    x * x
}

/// The 2x2 inverse `[[a, b], [c, d]]^-1` applied to `(p, q)`.
fn solve2(a: D, b: D, cc: D, d: D, p: D, q: D) -> (D, D) {
    let det = a * d - b * cc;
    ((d * p - b * q) / det, (a * q - cc * p) / det)
}

/// The solution of the 3x3 system `m x = y` (Gaussian elimination with partial pivoting).
fn solve3(mut m: [[D; 3]; 3], mut y: [D; 3]) -> [D; 3] {
    for col in 0..3 {
        let p = (col..3)
            .max_by(|&i, &j| m[i][col].value.abs().total_cmp(&m[j][col].value.abs()))
            .unwrap_or(col);
        m.swap(col, p);
        y.swap(col, p);
        for row in col + 1..3 {
            let f = m[row][col] / m[col][col];
            let pivot = m[col];
            for (a, b) in m[row].iter_mut().zip(pivot).skip(col) {
                *a = *a - f * b;
            }
            y[row] = y[row] - f * y[col];
        }
    }
    let mut x = [c(0.0); 3];
    for row in (0..3).rev() {
        let mut s = y[row];
        for k in row + 1..3 {
            s = s - m[row][k] * x[k];
        }
        x[row] = s / m[row][row];
    }
    x
}

/// $\lambda$ from the offsets (module docs): Newton's method on the values, then its
/// derivatives by the implicit function theorem.
fn lambda_from_abc(rf: D, rr: D, a: D, b: D, cc: D) -> Result<D, RawError> {
    let f = |l: D| l.sin() - (rf - rr + cc * l.cos()) / (a + b);
    let mut lam = (cc.value / (a.value + b.value)).atan();
    for _ in 0..100 {
        let fl = f(c(lam)).value;
        let dfl = lam.cos() + cc.value * lam.sin() / (a.value + b.value);
        let step = fl / dfl;
        lam -= step;
        if step.abs() <= 1e-15 * lam.abs().max(1.0) {
            break;
        }
    }
    if !lam.is_finite() {
        return Err(RawError::Unsupported {
            key: "h1".to_string(),
            reason: "the offsets h1-h5, d1-d4, d give no steer axis tilt".to_string(),
        });
    }
    // f(lambda(p), p) = 0: dlambda = -f_p / f_lambda.
    let fp = f(c(lam));
    let dfl = lam.cos() + cc.value * lam.sin() / (a.value + b.value);
    let mut out = c(lam);
    for (g, d) in out.grad.iter_mut().zip(fp.grad) {
        *g = -d / dfl;
    }
    Ok(out)
}

/// The least-squares solution of `m x = y` for `m` of `n >= 3` rows (the normal equations;
/// numpy's pseudo-inverse for a full column rank), exactly [`solve3`] for three rows.
fn least_squares(m: &[[D; 3]], y: &[D]) -> [D; 3] {
    if m.len() == 3 {
        return solve3([m[0], m[1], m[2]], [y[0], y[1], y[2]]);
    }
    let mut a = [[c(0.0); 3]; 3];
    let mut b = [c(0.0); 3];
    for (row, yr) in m.iter().zip(y) {
        for i in 0..3 {
            for k in 0..3 {
                a[i][k] = a[i][k] + row[i] * row[k];
            }
            b[i] = b[i] + row[i] * *yr;
        }
    }
    solve3(a, b)
}

/// $rcsin$ through [`Dual::atan2`].
fn asin(x: D) -> D {
    x.atan2((c(1.0) - sq(x)).sqrt())
}

/// A frame hung from the pendulum: its part letter and, per orientation, the line through its
/// mass centre (slope, intercept), the angle $eta$ and the key of its torsional period.
struct Hung {
    part: char,
    lines: Vec<(D, D, D, String)>,
}

/// The mean of the intersections of every ordered pair of lines (BicycleParameters'
/// `com.center_of_mass`).
fn centre_of(lines: &[(D, D, D, String)]) -> (D, D) {
    let (mut sx, mut sz, mut count) = (c(0.0), c(0.0), 0);
    for i in 0..lines.len() {
        for j in 0..lines.len() {
            if i == j {
                continue;
            }
            // [-m_i 1; -m_j 1] (x, z) = (b_i, b_j)
            let (x, z) = solve2(
                c(0.0) - lines[i].0,
                c(1.0),
                c(0.0) - lines[j].0,
                c(1.0),
                lines[i].1,
                lines[j].1,
            );
            (sx, sz, count) = (sx + x, sz + z, count + 1);
        }
    }
    (sx / c(count as f64), sz / c(count as f64))
}

/// The benchmark parameters of the raw measurements `text` (see the [module docs](self)).
///
/// # Errors
/// [`RawError`] naming the line, the missing measurement or the unsupported key.
pub fn benchmark_from_measured(text: &str) -> Result<Raw, RawError> {
    let mp = Measurements::read(text)?;
    let n = |k: &str| mp.need(k);
    // BicycleParameters' `is_fork_split`: any key starting with S or with S second.
    let split = mp.entries.iter().any(|(k, _)| k.starts_with('S') || k.get(1..2) == Some("S"));
    let rf = n("dF")? / c(2.0) / c(PI) / n("nF")?;
    let rr = n("dR")? / c(2.0) / c(PI) / n("nR")?;
    let (lam, w, fork_offset) = if mp.has("w") {
        let lam = c(PI / 180.0) * (c(90.0) - n("gamma")?);
        (lam, n("w")?, n("f")?)
    } else {
        let (h1, h2, h3, h4, h5) = (n("h1")?, n("h2")?, n("h3")?, n("h4")?, n("h5")?);
        let (d1, d2, d3, d4, d) = (n("d1")?, n("d2")?, n("d3")?, n("d4")?, n("d")?);
        let a = h1 + h2 - h3 + c(0.5) * d1 - c(0.5) * d2;
        let b = h4 - c(0.5) * d3 - h5 + c(0.5) * d4;
        let cc = (c(0.0) - sq(a - b) + sq(d + c(0.5) * (d2 + d3))).sqrt();
        let lam = lambda_from_abc(rf, rr, a, b, cc)?;
        let w = (a + b) * lam.cos() + cc * lam.sin();
        (lam, w, b)
    };
    let trail = (rf * lam.sin() - fork_offset) / lam.cos();
    let (mb, mf, mr, g) = (n("mB")?, n("mF")?, n("mR")?, n("g")?);
    // The handlebar's reference point from the front wheel centre (split fork only).
    let (u1, u2) = if split {
        let (r5, r6) = (n("d5")? / c(2.0), n("d6")? / c(2.0));
        let l1 = n("h7")? - n("h6")? + r5 - r6;
        let l0 = n("l")? - r5 - r6;
        let l2 = l0 * asin(l1 / l0).cos();
        let u1 = l2 * lam.sin() - l1 * lam.cos();
        (u1, u1 / lam.tan() + l1 / lam.sin())
    } else {
        (c(0.0), c(0.0))
    };

    // The mass-centre lines of each frame, in the order of the sorted `alpha` keys.
    let mut alpha_keys: Vec<&str> =
        mp.entries.iter().map(|(k, _)| k.as_str()).filter(|k| k.starts_with("alpha")).collect();
    alpha_keys.sort_unstable();
    let parts: &[char] = if split { &['B', 'G', 'S'] } else { &['B', 'H'] };
    let mut hung: Vec<Hung> = parts.iter().map(|&part| Hung { part, lines: Vec::new() }).collect();
    for key in alpha_keys {
        let alpha = n(key)?;
        let a = n(&format!("a{}", &key[5..]))?;
        let part = key[5..].chars().next().unwrap_or(' ');
        let beta = lam - alpha * c(PI) / c(180.0);
        let m = c(0.0) - beta.tan();
        let b = match part {
            'B' => c(0.0) - a / beta.cos() - rr,
            'H' | 'S' => c(0.0) - a / beta.cos() - rf + w * beta.tan(),
            'G' => c(0.0) - a / beta.cos() - (rf + u2) + (w - u1) * beta.tan(),
            _ => c(f64::NAN),
        };
        let slot =
            hung.iter_mut().find(|h| h.part == part).ok_or_else(|| RawError::Unsupported {
                key: key.to_string(),
                reason: format!(
                    "unknown part {part} (expected {})",
                    parts.iter().map(char::to_string).collect::<Vec<_>>().join(", ")
                ),
            })?;
        slot.lines.push((m, b, beta, format!("Tt{}", &key[5..])));
    }
    for h in &hung {
        if h.lines.len() < 3 {
            return Err(RawError::Unsupported {
                key: format!("alpha{}", h.part),
                reason: format!(
                    "the frame {} is hung in {} orientations; its inertia needs at least 3",
                    h.part,
                    h.lines.len()
                ),
            });
        }
    }
    let centres: Vec<(D, D)> = hung.iter().map(|h| centre_of(&h.lines)).collect();
    let centre = |part: char| centres[parts.iter().position(|p| *p == part).unwrap_or(0)];

    let compound = |m: D, l: D, t: D| sq(t / c(2.0) / c(PI)) * m * g * l - m * sq(l);
    let ifyy = compound(mf, n("lF")?, n("TcF1")?);
    let iryy = compound(mr, n("lR")?, n("TcR1")?);
    let (xb, zb) = centre('B');
    let lb = (sq(xb) + sq(zb + rr)).sqrt();
    let ibyy = compound(mb, lb, n("TcB1")?);

    let ro = n("dP")? / c(2.0);
    let ipyy = n("mP")? / c(12.0) * (c(3.0) * sq(ro) + c(3.0) * sq(c(0.0)) + sq(n("lP")?));
    let stiffness = c(4.0) * ipyy * sq(c(PI)) / sq(n("TtP1")?);
    let torsional = |t: D| stiffness * sq(t) / c(4.0) / sq(c(PI));
    let ifxx = torsional(n("TtF1")?);
    let irxx = torsional(n("TtR1")?);
    let mut planar = Vec::with_capacity(hung.len());
    for h in &hung {
        let mut m = Vec::with_capacity(h.lines.len());
        let mut j = Vec::with_capacity(h.lines.len());
        for (_, _, beta, key) in &h.lines {
            let (sb, cb) = (beta.sin(), beta.cos());
            m.push([sq(cb), c(-2.0) * sb * cb, sq(sb)]);
            j.push(torsional(n(key)?));
        }
        planar.push(least_squares(&m, &j));
    }
    let inertia = |part: char| planar[parts.iter().position(|p| *p == part).unwrap_or(0)];
    let [ibxx, ibxz, ibzz] = inertia('B');

    // The front frame: measured whole, or its fork S and handlebar G combined.
    let (mh, xh, zh, ihxx, ihxz, ihyy, ihzz) = if split {
        let (ms, mg) = (n("mS")?, n("mG")?);
        let ((xs, zs), (xg, zg)) = (centre('S'), centre('G'));
        let ls = (sq(xs - w) + sq(zs + rf)).sqrt();
        let isyy = compound(ms, ls, n("TcS1")?);
        let lg = (sq(xg - w + u1) + sq(zg + rf + u2)).sqrt();
        let igyy = compound(mg, lg, n("TcG1")?);
        let mh = mg + ms;
        let (xh, zh) = ((mg * xg + ms * xs) / mh, (mg * zg + ms * zs) / mh);
        let ([igxx, igxz, igzz], [isxx, isxz, iszz]) = (inertia('G'), inertia('S'));
        let (dgx, dgz, dsx, dsz) = (xg - xh, zg - zh, xs - xh, zs - zh);
        let zero = c(0.0);
        (
            mh,
            xh,
            zh,
            igxx + mg * (sq(zero) + sq(dgz)) + (isxx + ms * (sq(zero) + sq(dsz))),
            igxz + mg * (zero - dgx * dgz) + (isxz + ms * (zero - dsx * dsz)),
            igyy + mg * (sq(dgz) + sq(dgx)) + (isyy + ms * (sq(dsz) + sq(dsx))),
            igzz + mg * (sq(dgx) + sq(zero)) + (iszz + ms * (sq(dsx) + sq(zero))),
        )
    } else {
        let mh = n("mH")?;
        let (xh, zh) = centre('H');
        let lh = (sq(xh - w) + sq(zh + rf)).sqrt();
        let ihyy = compound(mh, lh, n("TcH1")?);
        let [ihxx, ihxz, ihzz] = inertia('H');
        (mh, xh, zh, ihxx, ihxz, ihyy, ihzz)
    };
    // A flywheel D in the front wheel (measured together with it): not part of the model, as
    // BicycleParameters' own analysis ignores it; returned beside the parameters.
    let mut extra = Vec::new();
    if mp.has("mD") {
        let md = n("mD")? - mf;
        let idyy = compound(n("mD")?, n("lF")?, n("TcD1")?) - ifyy;
        let idxx = torsional(n("TtD1")?) - ifxx;
        extra =
            vec![("mD".to_string(), md), ("IDxx".to_string(), idxx), ("IDyy".to_string(), idyy)];
    }

    let by_name = |name: &str| -> D {
        match name {
            "w" => w,
            "c" => trail,
            "lambda" => lam,
            "g" => g,
            "rR" => rr,
            "mR" => mr,
            "IRxx" => irxx,
            "IRyy" => iryy,
            "xB" => xb,
            "zB" => zb,
            "mB" => mb,
            "IBxx" => ibxx,
            "IByy" => ibyy,
            "IBzz" => ibzz,
            "IBxz" => ibxz,
            "xH" => xh,
            "zH" => zh,
            "mH" => mh,
            "IHxx" => ihxx,
            "IHyy" => ihyy,
            "IHzz" => ihzz,
            "IHxz" => ihxz,
            "rF" => rf,
            "mF" => mf,
            "IFxx" => ifxx,
            "IFyy" => ifyy,
            _ => c(f64::NAN),
        }
    };
    let values: [D; 26] = std::array::from_fn(|i| by_name(PARAM_NAMES[i]));
    let k = mp.names.len();
    let jacobian: Vec<Vec<f64>> = values.iter().map(|v| v.grad[..k].to_vec()).collect();
    let sigma: [f64; 26] = std::array::from_fn(|i| {
        jacobian[i].iter().zip(&mp.sigma).map(|(d, s)| (d * s) * (d * s)).sum::<f64>().sqrt()
    });
    let params = WhippleParams::from_values_warning(values.map(|v| v.value))
        .map_err(|e| RawError::Unsupported {
            key: "parameters".to_string(),
            reason: format!("the measurements give no valid bicycle: {e}"),
        })?
        .0;
    let std = |v: &D| -> f64 {
        v.grad[..k].iter().zip(&mp.sigma).map(|(d, s)| (d * s) * (d * s)).sum::<f64>().sqrt()
    };
    let extra = extra.iter().map(|(name, v)| (name.clone(), v.value, std(v))).collect();
    Ok(Raw {
        params: UncertainParams { params, sigma },
        extra,
        measured: mp.names,
        measured_sigma: mp.sigma,
        jacobian,
    })
}
