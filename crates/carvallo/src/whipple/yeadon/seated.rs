//! A Yeadon body seated on a bicycle, as BicycleParameters 1.5.2 seats it
//! (`rider.rider_on_bike` and `configure_rider`, used by `Bicycle.add_rider(reCalc=True)`):
//! the joint angles that put the hips on the seat, the ankles level with the bottom bracket's
//! axis and the hands on the handlebar, then the body's mass, mass centre and inertia in the
//! bicycle's frame.
//!
//! # The equations
//! With the somersault (forward lean of the pelvis) $\varphi_P$ given by the configuration
//! file, ten unknowns: the hip extension $\varphi_{J1}$ and knee flexion $\varphi_{J2}$, the
//! shoulder's extension $\varphi_{A1}$, adduction $\theta_{A1}$ and rotation $\psi_A$, the
//! elbow's extension $\varphi_{A2}$, and the hand's position $(\alpha_y, \alpha_z)$ from the
//! front hub and $(\beta_y, \beta_z)$ from the rear hub. Ten equations (BicycleParameters'
//! `zero`, derived in yeadon's `bicycle_example` notebook): the ankle of the leg, stretched
//! from the hip at the seat (the top of the seat tube and post, $l_{st} + l_{sp}$ along the
//! seat tube angle $\lambda_{st}$) through the knee, lies in the plane of the bottom bracket
//! (two equations); the hand lies at the measured distances $L_{hbF}$, $L_{hbR}$ from the hubs
//! and half the handlebar width $w_{hb}$ to the side (four, with the wheelbase $w$ and the wheel
//! radii); the hand reached by the arm from the shoulder is that point (three); the forearm's
//! roll is zero (one). The right side mirrors the left (`PK1extension = PJ1extension`,
//! `CB1abduction = -CA1adduction`, ...); the other joint angles are the configuration file's.
//!
//! BicycleParameters solves them with SciPy's `fsolve` (MINPACK's `hybrd`, relative step
//! tolerance `xtol` $1.5\cdot10^{-8}$) from a fixed initial guess; here Newton's method from the
//! same guess, with a central-difference Jacobian, until the step stops decreasing — the
//! residual is then at rounding ($\sim 10^{-16}$ m), so the angles are those of the equations,
//! and BicycleParameters' differ from them by what `xtol` lets through (about $10^{-8}$
//! relative in the angles, $10^{-7}$ in the rider's inertia).
//!
//! # The frames
//! yeadon's body frame ($x$ left, $y$ forward, $z$ up, from the centre of `Ls0`) is turned to
//! the bicycle's ($x$ forward, $y$ right, $z$ down) by $R = \begin{pmatrix}0&-1&0\\-1&0&0\\0&0&-1\end{pmatrix}$;
//! the origin of yeadon's frame is the top of the seat post,
//! $\big(\sqrt{l_{cs}^2 - (r_R - h_{bb})^2} - (l_{sp} + l_{st})\cos\lambda_{st},\ 0,\ -h_{bb} - (l_{sp} + l_{st})\sin\lambda_{st}\big)$
//! from the rear contact. The inertia is carried as BicycleParameters does,
//! $R^T I R$ (`Human.inertia_transformed`).

use nalgebra::{SMatrix, SVector};

use super::human::{Human, MassProperties};
use super::{Configuration, Measurements, Variant, YeadonError};
use crate::whipple::parameter_text::Rider;
use crate::whipple::raw::{nominal_measurements, RawError};
use crate::whipple::WhippleParams;

/// What the seating needs of the bicycle: its measured geometry (BicycleParameters'
/// `RawData/<bicycle>Measured.txt`) and three benchmark parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeatingGeometry {
    /// Bottom bracket height `hbb` (m).
    pub hbb: f64,
    /// Chain stay length `lcs` (m).
    pub lcs: f64,
    /// Seat post length `lsp` (m).
    pub lsp: f64,
    /// Seat tube length `lst` (m).
    pub lst: f64,
    /// Seat tube angle `lamst` (rad, from the ground).
    pub lamst: f64,
    /// Handlebar width `whb` (m).
    pub whb: f64,
    /// Distance from the rear hub to the hand `LhbR` (m).
    pub lhbr: f64,
    /// Distance from the front hub to the hand `LhbF` (m).
    pub lhbf: f64,
    /// Rear wheel radius `rR` (m).
    pub rr: f64,
    /// Front wheel radius `rF` (m).
    pub rf: f64,
    /// Wheelbase `w` (m).
    pub w: f64,
}

/// The keys of a measured file the seating reads.
pub const SEATING_KEYS: [&str; 8] = ["hbb", "lcs", "lsp", "lst", "lamst", "whb", "LhbR", "LhbF"];

impl SeatingGeometry {
    /// The geometry of a BicycleParameters measured file (`<bicycle>Measured.txt`, nominal
    /// values) with `rR`, `rF`, `w` of the benchmark parameters `params` (BicycleParameters
    /// takes them from `Bicycle.parameters['Benchmark']`, the parameter file when there is one).
    ///
    /// # Errors
    /// A [`RawError`] for a bad line or a missing key of [`SEATING_KEYS`].
    pub fn from_measured(text: &str, params: &WhippleParams) -> Result<SeatingGeometry, RawError> {
        let values = nominal_measurements(text)?;
        let get = |key: &str| {
            values
                .iter()
                .find(|(n, _)| n == key)
                .map(|(_, v)| *v)
                .ok_or_else(|| RawError::Missing { key: key.to_string() })
        };
        let d = params.design();
        Ok(SeatingGeometry {
            hbb: get("hbb")?,
            lcs: get("lcs")?,
            lsp: get("lsp")?,
            lst: get("lst")?,
            lamst: get("lamst")?,
            whb: get("whb")?,
            lhbr: get("LhbR")?,
            lhbf: get("LhbF")?,
            rr: d.rear_wheel.radius,
            rf: d.front_wheel.radius,
            w: d.wheelbase,
        })
    }

    /// The top of the seat post (yeadon's origin) from the rear contact, in the bicycle frame.
    pub fn seat(&self) -> [f64; 3] {
        let g = self;
        [
            (g.lcs.powi(2) - (-g.hbb + g.rr).powi(2)).sqrt() + (-g.lsp - g.lst) * g.lamst.cos(),
            0.0,
            -g.hbb + (-g.lsp - g.lst) * g.lamst.sin(),
        ]
    }
}

/// The body lengths the seating reads (yeadon's `Human.meas` after averaging the limbs).
#[derive(Clone, Copy, Debug)]
struct Body {
    lj3l: f64,
    lj5l: f64,
    lj6l: f64,
    ls4l: f64,
    ls4w: f64,
    la2l: f64,
    la4l: f64,
    la5l: f64,
}

/// BicycleParameters' ten seating equations at `u` (see the [module docs](self)).
fn residual(u: &[f64; 10], b: &Body, g: &SeatingGeometry, phi_p: f64) -> [f64; 10] {
    let [phi_j1, phi_j2, phi_a1, theta_a1, psi_a, phi_a2, alpha_y, alpha_z, beta_y, beta_z] = *u;
    let (s, c) = (f64::sin, f64::cos);
    let (l_j3l, l_j5l, l_j6l) = (b.lj3l, b.lj5l, b.lj6l);
    let (l_s4l, l_s4w, l_a2l, l_a4l, l_a5l) = (b.ls4l, b.ls4w, b.la2l, b.la4l, b.la5l);
    let (h_bb, l_cs, r_r, r_f) = (g.hbb, g.lcs, g.rr, g.rf);
    let (l_sp, l_st, lambda_st, w_hb) = (g.lsp, g.lst, g.lamst, g.whb);
    let (l_hbr, l_hbf, w) = (g.lhbr, g.lhbf, g.w);
    let arm = l_a2l - l_a4l - l_a5l;
    let leg = -l_j3l + l_j5l + l_j6l;
    [
        l_j3l * (-s(phi_j1) * c(phi_p) - s(phi_p) * c(phi_j1))
            + (-l_sp - l_st) * c(lambda_st)
            + (-(-s(phi_j1) * s(phi_p) + c(phi_j1) * c(phi_p)) * s(phi_j2)
                + (-s(phi_j1) * c(phi_p) - s(phi_p) * c(phi_j1)) * c(phi_j2))
                * leg,
        l_j3l * (-s(phi_j1) * s(phi_p) + c(phi_j1) * c(phi_p))
            + (-l_sp - l_st) * s(lambda_st)
            + ((-s(phi_j1) * s(phi_p) + c(phi_j1) * c(phi_p)) * c(phi_j2)
                - (s(phi_j1) * c(phi_p) + s(phi_p) * c(phi_j1)) * s(phi_j2))
                * leg,
        -l_hbf + (alpha_y.powi(2) + alpha_z.powi(2) + 0.25 * w_hb.powi(2)).sqrt(),
        -l_hbr + (beta_y.powi(2) + beta_z.powi(2) + 0.25 * w_hb.powi(2)).sqrt(),
        alpha_y - beta_y - w,
        alpha_z - beta_z + r_f - r_r,
        -l_a2l * s(theta_a1) + l_s4w / 2.0 - 0.5 * w_hb
            + (s(phi_a2) * s(psi_a) * c(theta_a1) + s(theta_a1) * c(phi_a2)) * arm,
        -l_a2l * (-s(phi_a1) * c(phi_p) * c(theta_a1) - s(phi_p) * c(phi_a1) * c(theta_a1))
            - l_s4l * s(phi_p)
            - beta_y
            - (l_cs.powi(2) - (-h_bb + r_r).powi(2)).sqrt()
            - (-l_sp - l_st) * c(lambda_st)
            + (-(-(s(phi_a1) * c(psi_a) + s(psi_a) * s(theta_a1) * c(phi_a1)) * s(phi_p)
                + (-s(phi_a1) * s(psi_a) * s(theta_a1) + c(phi_a1) * c(psi_a)) * c(phi_p))
                * s(phi_a2)
                + (-s(phi_a1) * c(phi_p) * c(theta_a1) - s(phi_p) * c(phi_a1) * c(theta_a1))
                    * c(phi_a2))
                * arm,
        -l_a2l * (-s(phi_a1) * s(phi_p) * c(theta_a1) + c(phi_a1) * c(phi_p) * c(theta_a1))
            + l_s4l * c(phi_p)
            - beta_z
            + h_bb
            - r_r
            - (-l_sp - l_st) * s(lambda_st)
            + (-((s(phi_a1) * c(psi_a) + s(psi_a) * s(theta_a1) * c(phi_a1)) * c(phi_p)
                + (-s(phi_a1) * s(psi_a) * s(theta_a1) + c(phi_a1) * c(psi_a)) * s(phi_p))
                * s(phi_a2)
                + (-s(phi_a1) * s(phi_p) * c(theta_a1) + c(phi_a1) * c(phi_p) * c(theta_a1))
                    * c(phi_a2))
                * arm,
        (s(phi_a1) * s(psi_a) - s(theta_a1) * c(phi_a1) * c(psi_a)) * c(phi_p)
            + (s(phi_a1) * s(theta_a1) * c(psi_a) + s(psi_a) * c(phi_a1)) * s(phi_p),
    ]
}

/// BicycleParameters' initial guess.
fn initial_guess(g: &SeatingGeometry) -> [f64; 10] {
    let deg = f64::to_radians;
    [
        -deg(90.0),
        deg(75.0),
        -deg(15.0),
        deg(2.0),
        deg(2.0),
        -deg(40.0),
        g.lhbf * deg(45.0).cos(),
        g.lhbf * deg(45.0).sin(),
        -g.lhbr * deg(30.0).cos(),
        g.lhbr * deg(30.0).sin(),
    ]
}

fn max_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0, |m, v| m.max(v.abs()))
}

/// Newton's method on [`residual`] from BicycleParameters' guess; `(solution, residual,
/// iterations)`.
fn solve(
    b: &Body,
    g: &SeatingGeometry,
    phi_p: f64,
) -> Result<([f64; 10], f64, usize), YeadonError> {
    let f = |u: &[f64; 10]| residual(u, b, g, phi_p);
    let mut u = initial_guess(g);
    let mut r = f(&u);
    let mut last_step = f64::INFINITY;
    for it in 1..=100 {
        let mut jac = SMatrix::<f64, 10, 10>::zeros();
        for j in 0..10 {
            let h = 1e-7 * u[j].abs().max(1.0);
            let (mut up, mut down) = (u, u);
            up[j] += h;
            down[j] -= h;
            let (fu, fd) = (f(&up), f(&down));
            for i in 0..10 {
                jac[(i, j)] = (fu[i] - fd[i]) / (2.0 * h);
            }
        }
        let rhs = -SVector::<f64, 10>::from_row_slice(&r);
        let Some(step) = jac.lu().solve(&rhs) else {
            return Err(YeadonError::NoSeating { residual: max_abs(&r), iterations: it });
        };
        let size = max_abs(step.as_slice());
        if !size.is_finite() {
            return Err(YeadonError::NoSeating { residual: max_abs(&r), iterations: it });
        }
        // Near the root the step falls to rounding and stops decreasing: stop there, keeping
        // the iterate with the smaller residual.
        let trial: [f64; 10] = std::array::from_fn(|k| u[k] + step[k]);
        let rt = f(&trial);
        if size >= last_step && size < 1e-12 {
            if max_abs(&rt) < max_abs(&r) {
                (u, r) = (trial, rt);
            }
            return finish(u, r, it);
        }
        (u, r, last_step) = (trial, rt, size);
        if size == 0.0 {
            return finish(u, r, it);
        }
    }
    Err(YeadonError::NoSeating { residual: max_abs(&r), iterations: 100 })
}

fn finish(u: [f64; 10], r: [f64; 10], it: usize) -> Result<([f64; 10], f64, usize), YeadonError> {
    let res = max_abs(&r);
    if res > 1e-12 {
        return Err(YeadonError::NoSeating { residual: res, iterations: it });
    }
    Ok((u, res, it))
}

/// A body seated on a bicycle.
#[derive(Clone, Debug, PartialEq)]
pub struct SeatedRider {
    /// The configuration: the file's, with the 13 angles the seating sets.
    pub configuration: Configuration,
    /// The body in yeadon's frame (mass centre from the top of the seat post).
    pub body: MassProperties,
    /// The rider's rigid body in the bicycle's frame, as BicycleParameters' `riderPar`
    /// (`mB, xB, yB, zB, IBxx, IBxz, IByy, IBzz`, no uncertainty), ready for
    /// [`add_rider`](crate::whipple::parameter_text::add_rider).
    pub rider: Rider,
    /// The hand's position from the front hub `(alpha_y, alpha_z)` and from the rear hub
    /// `(beta_y, beta_z)` in the seating's plane (m).
    pub hands: [f64; 4],
    /// The largest residual of the ten seating equations at the solution (m or rad).
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
    /// What was done beside the files as given (yeadon's substitutions, angles out of bounds).
    pub notes: Vec<String>,
}

/// Seats the body of `measurements` in the configuration `cfg` (its somersault and the angles
/// the seating does not set) on the bicycle of geometry `g` (BicycleParameters'
/// `configure_rider`); [`Variant::Published`] reproduces yeadon 2.0.1.
///
/// # Errors
/// [`YeadonError::Parameter`] for measurements that give no body; [`YeadonError::NoSeating`]
/// when Newton's method from BicycleParameters' guess finds no seating (the arms cannot reach
/// the handlebar, or the legs the pedals' plane).
pub fn seat_on_bicycle(
    measurements: &Measurements,
    cfg: &Configuration,
    g: &SeatingGeometry,
    variant: Variant,
) -> Result<SeatedRider, YeadonError> {
    let human = Human::new(measurements, variant)?;
    // The lengths after averaging the limbs, as yeadon's `Human.meas`.
    let avg = |a: &str, b: &str| 0.5 * (measurements.get(a) + measurements.get(b));
    let body = Body {
        lj3l: avg("Lj3L", "Lk3L"),
        lj5l: avg("Lj5L", "Lk5L"),
        lj6l: avg("Lj6L", "Lk6L"),
        ls4l: measurements.get("Ls4L"),
        ls4w: measurements.get("Ls4w"),
        la2l: avg("La2L", "Lb2L"),
        la4l: avg("La4L", "Lb4L"),
        la5l: avg("La5L", "Lb5L"),
    };
    let phi_p = cfg.get("somersault");
    let (u, residual, iterations) = solve(&body, g, phi_p)?;
    let mut c = *cfg;
    for (name, v) in [
        ("PJ1extension", u[0]),
        ("J1J2flexion", u[1]),
        ("CA1extension", u[2]),
        ("CA1adduction", u[3]),
        ("CA1rotation", u[4]),
        ("A1A2extension", u[5]),
        ("PK1extension", u[0]),
        ("K1K2flexion", u[1]),
        ("CB1extension", u[2]),
        ("CB1abduction", -u[3]),
        ("CB1rotation", -u[4]),
        ("B1B2extension", u[5]),
    ] {
        c.set(name, v);
    }
    let p = human.mass_properties(&c);
    // Yeadon's frame to the bicycle's: x_b = -y, y_b = -x, z_b = -z.
    let rot = [[0.0, -1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]];
    // R^T I R (Human.inertia_transformed with rotmat = R).
    let inertia: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = 0.0;
            for k in 0..3 {
                for l in 0..3 {
                    s += rot[k][i] * p.inertia[k][l] * rot[l][j];
                }
            }
            s
        })
    });
    let seat = g.seat();
    let centre: [f64; 3] =
        std::array::from_fn(|i| seat[i] + (0..3).fold(0.0, |acc, k| acc + rot[i][k] * p.centre[k]));
    let rider = Rider {
        values: [
            p.mass,
            centre[0],
            centre[1],
            centre[2],
            inertia[0][0],
            inertia[2][0],
            inertia[1][1],
            inertia[2][2],
        ],
        sigma: [0.0; 8],
    };
    let mut notes = human.notes().to_vec();
    notes.extend(c.out_of_bounds());
    Ok(SeatedRider {
        configuration: c,
        body: p,
        rider,
        hands: [u[6], u[7], u[8], u[9]],
        residual,
        iterations,
        notes,
    })
}

/// Where BicycleParameters' data layout keeps the other two files of a seating, given the
/// rider's measurement file `<data>/riders/<R>/RawData/<R>YeadonMeas.txt` and the bicycle's
/// parameter file `<data>/bicycles/<B>/Parameters/<B>Benchmark.txt`: the configuration
/// `<data>/riders/<R>/RawData/<R><B>YeadonCFG.txt` and the measured geometry
/// `<data>/bicycles/<B>/RawData/<B>Measured.txt` (the files `Bicycle.add_rider(R, reCalc=True)`
/// reads). `None` when the names do not follow the layout; the files may not exist.
pub fn bicycleparameters_files(
    measurements: &std::path::Path,
    bicycle: &std::path::Path,
) -> Option<(std::path::PathBuf, std::path::PathBuf)> {
    let stem = |p: &std::path::Path| p.file_stem().map(|s| s.to_string_lossy().into_owned());
    let b = stem(bicycle)?.strip_suffix("Benchmark").filter(|b| !b.is_empty())?.to_string();
    let r = stem(measurements)?.strip_suffix("YeadonMeas").filter(|r| !r.is_empty())?.to_string();
    let cfg = measurements.with_file_name(format!("{r}{b}YeadonCFG.txt"));
    let bike_dir = bicycle.parent()?.parent()?;
    let measured = bike_dir.join("RawData").join(format!("{b}Measured.txt"));
    Some((cfg, measured))
}

/// A one-line account of a seating, for the outputs that say what was done: the body's mass,
/// the solved angles and the residual.
pub fn describe(seated: &SeatedRider) -> String {
    let c = &seated.configuration;
    let deg = |n: &str| c.get(n).to_degrees();
    format!(
        "Yeadon body of {:.2} kg seated by BicycleParameters' equations (somersault {:.2}°, \
         hip {:.2}°, knee {:.2}°, shoulder {:.2}°/{:.2}°/{:.2}°, elbow {:.2}°; residual {:.1e} \
         after {} Newton iterations): mB = {:?}, xB = {:?}, zB = {:?}",
        seated.rider.values[0],
        deg("somersault"),
        deg("PJ1extension"),
        deg("J1J2flexion"),
        deg("CA1extension"),
        deg("CA1adduction"),
        deg("CA1rotation"),
        deg("A1A2extension"),
        seated.residual,
        seated.iterations,
        seated.rider.values[0],
        seated.rider.values[1],
        seated.rider.values[3],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");

    fn read(path: &str) -> String {
        std::fs::read_to_string(format!("{DATA}/{path}")).expect("data file")
    }

    #[test]
    fn jason_sits_on_the_browser_with_the_equations_met_to_rounding() {
        let meas = Measurements::from_text(&read("riders/Jason/RawData/JasonYeadonMeas.txt"))
            .expect("valid");
        let cfg = Configuration::from_text(&read("riders/Jason/RawData/JasonBrowserYeadonCFG.txt"))
            .expect("valid");
        let bike = crate::whipple::parameter_text::UncertainParams::read(
            &read("bicycles/Browser/Parameters/BrowserBenchmark.txt"),
            false,
        )
        .expect("valid")
        .params;
        let g = SeatingGeometry::from_measured(
            &read("bicycles/Browser/RawData/BrowserMeasured.txt"),
            &bike.params,
        )
        .expect("valid");
        let seated = seat_on_bicycle(&meas, &cfg, &g, Variant::Published).expect("seated");
        assert!(seated.residual < 1e-14, "{}", seated.residual);
        assert!((seated.rider.values[0] - 83.5).abs() < 1e-12);
        // The rider sits above the seat, ahead of the rear contact, between the wheels.
        let [_, x, y, z, ixx, _, iyy, izz] = seated.rider.values;
        assert!(x > 0.0 && x < g.w && z < -1.0 && y.abs() < 1e-12, "{:?}", seated.rider);
        assert!(ixx > 0.0 && iyy > 0.0 && izz > 0.0);
        // Hands at the handlebar's measured distances from the hubs.
        let [ay, az, by, bz] = seated.hands;
        let half = 0.25 * g.whb * g.whb;
        assert!(((ay * ay + az * az + half).sqrt() - g.lhbf).abs() < 1e-14);
        assert!(((by * by + bz * bz + half).sqrt() - g.lhbr).abs() < 1e-14);
    }

    #[test]
    fn the_layout_names_the_other_files() {
        let (cfg, measured) = bicycleparameters_files(
            std::path::Path::new("d/riders/Jason/RawData/JasonYeadonMeas.txt"),
            std::path::Path::new("d/bicycles/Browser/Parameters/BrowserBenchmark.txt"),
        )
        .expect("the layout");
        assert_eq!(cfg, std::path::Path::new("d/riders/Jason/RawData/JasonBrowserYeadonCFG.txt"));
        assert_eq!(
            measured,
            std::path::Path::new("d/bicycles/Browser/RawData/BrowserMeasured.txt")
        );
        assert!(bicycleparameters_files(
            std::path::Path::new("jason.yaml"),
            std::path::Path::new("BrowserBenchmark.txt")
        )
        .is_none());
    }

    #[test]
    fn an_unreachable_handlebar_is_refused() {
        let meas = Measurements::from_text(&read("riders/Jason/RawData/JasonYeadonMeas.txt"))
            .expect("valid");
        let cfg = Configuration::from_text(&read("riders/Jason/RawData/JasonBrowserYeadonCFG.txt"))
            .expect("valid");
        let mut g = SeatingGeometry::from_measured(
            &read("bicycles/Browser/RawData/BrowserMeasured.txt"),
            &WhippleParams::benchmark(),
        )
        .expect("valid");
        g.lhbf = 3.0;
        g.lhbr = 3.0;
        let e = seat_on_bicycle(&meas, &cfg, &g, Variant::Published).unwrap_err();
        assert!(matches!(e, YeadonError::NoSeating { .. }), "{e}");
    }
}
