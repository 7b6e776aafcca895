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
//! Not computed (an error naming the key): a front frame measured in two parts (fork `S`,
//! handlebar `G`), a flywheel `D`, and frames hung in more than three orientations.

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

/// The benchmark parameters computed from raw measurements.
#[derive(Clone, Debug)]
pub struct Raw {
    /// The parameters and their standard deviations.
    pub params: UncertainParams,
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
        let mut c = [[0.0; 26]; 26];
        for i in 0..26 {
            for k in 0..26 {
                c[i][k] = (0..self.measured.len())
                    .map(|j| {
                        let s = self.measured_sigma[j];
                        self.jacobian[i][j] * self.jacobian[k][j] * s * s
                    })
                    .sum();
            }
        }
        c
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
            for k in col..3 {
                m[row][k] = m[row][k] - f * m[col][k];
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

/// The benchmark parameters of the raw measurements `text` (see the [module docs](self)).
///
/// # Errors
/// [`RawError`] naming the line, the missing measurement or the unsupported key.
pub fn benchmark_from_measured(text: &str) -> Result<Raw, RawError> {
    let mp = Measurements::read(text)?;
    for (key, what) in [
        ("mS", "a front frame measured in two parts (fork S, handlebar G)"),
        ("mG", "a front frame measured in two parts (fork S, handlebar G)"),
        ("mD", "a flywheel D"),
    ] {
        if mp.has(key) {
            return Err(RawError::Unsupported {
                key: key.to_string(),
                reason: format!("{what} is not handled by this computation"),
            });
        }
    }
    let n = |k: &str| mp.need(k);
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
    let (mb, mf, mr, mh, g) = (n("mB")?, n("mF")?, n("mR")?, n("mH")?, n("g")?);

    // The mass-centre lines of each frame, in the order of the sorted `alpha` keys.
    let mut alpha_keys: Vec<&str> =
        mp.entries.iter().map(|(k, _)| k.as_str()).filter(|k| k.starts_with("alpha")).collect();
    alpha_keys.sort_unstable();
    let mut lines: [Vec<(D, D, D, String)>; 2] = [Vec::new(), Vec::new()];
    for key in alpha_keys {
        let alpha = n(key)?;
        let a = n(&format!("a{}", &key[5..]))?;
        let part = &key[5..6];
        let beta = lam - alpha * c(PI) / c(180.0);
        let m = c(0.0) - beta.tan();
        let (slot, b) = match part {
            "B" => (0, c(0.0) - a / beta.cos() - rr),
            "H" => (1, c(0.0) - a / beta.cos() - rf + w * beta.tan()),
            _ => {
                return Err(RawError::Unsupported {
                    key: key.to_string(),
                    reason: format!("unknown part {part} (expected B or H)"),
                })
            }
        };
        lines[slot].push((m, b, beta, format!("Tt{}", &key[5..])));
    }
    let mut centre = [(c(0.0), c(0.0)); 2];
    for (slot, part) in [(0, "B"), (1, "H")] {
        let l = &lines[slot];
        if l.len() != 3 {
            return Err(RawError::Unsupported {
                key: format!("alpha{part}"),
                reason: format!(
                    "the frame {part} is hung in {} orientations; this computation takes 3",
                    l.len()
                ),
            });
        }
        let (mut sx, mut sz, mut count) = (c(0.0), c(0.0), 0);
        for i in 0..l.len() {
            for j in 0..l.len() {
                if i == j {
                    continue;
                }
                // [-m_i 1; -m_j 1] (x, z) = (b_i, b_j)
                let (x, z) =
                    solve2(c(0.0) - l[i].0, c(1.0), c(0.0) - l[j].0, c(1.0), l[i].1, l[j].1);
                (sx, sz, count) = (sx + x, sz + z, count + 1);
            }
        }
        centre[slot] = (sx / c(count as f64), sz / c(count as f64));
    }
    let [(xb, zb), (xh, zh)] = centre;

    let compound = |m: D, l: D, t: D| sq(t / c(2.0) / c(PI)) * m * g * l - m * sq(l);
    let ifyy = compound(mf, n("lF")?, n("TcF1")?);
    let iryy = compound(mr, n("lR")?, n("TcR1")?);
    let lb = (sq(xb) + sq(zb + rr)).sqrt();
    let ibyy = compound(mb, lb, n("TcB1")?);
    let lh = (sq(xh - w) + sq(zh + rf)).sqrt();
    let ihyy = compound(mh, lh, n("TcH1")?);

    let ro = n("dP")? / c(2.0);
    let ipyy = n("mP")? / c(12.0) * (c(3.0) * sq(ro) + c(3.0) * sq(c(0.0)) + sq(n("lP")?));
    let stiffness = c(4.0) * ipyy * sq(c(PI)) / sq(n("TtP1")?);
    let torsional = |t: D| stiffness * sq(t) / c(4.0) / sq(c(PI));
    let ifxx = torsional(n("TtF1")?);
    let irxx = torsional(n("TtR1")?);
    let mut planar = [[c(0.0); 3]; 2];
    for slot in 0..2 {
        let l = &lines[slot];
        let mut m = [[c(0.0); 3]; 3];
        let mut j = [c(0.0); 3];
        for (i, (_, _, beta, key)) in l.iter().enumerate() {
            let (sb, cb) = (beta.sin(), beta.cos());
            m[i] = [sq(cb), c(-2.0) * sb * cb, sq(sb)];
            j[i] = torsional(n(key)?);
        }
        planar[slot] = solve3(m, j);
    }
    let [[ibxx, ibxz, ibzz], [ihxx, ihxz, ihzz]] = planar;

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
    Ok(Raw {
        params: UncertainParams { params, sigma },
        measured: mp.names,
        measured_sigma: mp.sigma,
        jacobian,
    })
}
