//! Hands-free steady turns (memoir n° 97: «sans les mains»): the turns that need no steer
//! torque, $f_{3,1} = f_{3,2} = 0$ (rows lean and steer, [`super`]), two equations in the
//! speed, the lean and the steer, so curves in $(v, \varphi, \delta)$, the pitch solved from the
//! front contact at every point.
//!
//! Upright running, straight ahead ($\varphi = \delta = 0$) or with the handlebar reversed
//! ($\delta = \pi$), solves both equations at every speed: two lines of solutions. The curved
//! families branch from them where the Jacobian of the two rows in (lean, steer) is singular;
//! on the forward line that Jacobian is $-(gK_0 + v^2K_2)$ (the linearised model's static
//! stiffness), whose determinant, the characteristic polynomial's constant term, is affine in
//! $v^2$ ($K_2$'s first column is zero): one branch point, at the capsize speed.
//! [`HandsFree::branch_speeds`] finds the branch points of a line by a scan of that
//! determinant (the Jacobian of the nonlinear rows from generated derivatives,
//! [`super::turn_rows_scene`], not the linear matrices) and bisection.
//!
//! A family is followed from a branch point by pseudo-arclength continuation
//! ([`HandsFree::family`]): a first point off the line along the null vector of the stiffness
//! (the lean fixed, Newton on speed and steer), then predictor steps along the unit tangent
//! $t$ (the cross product of the two rows' gradients, oriented as the step before) and Newton
//! corrections on $F = 0$, $t\cdot(z - z_0) = h$ in $z = (v, \varphi, \delta)$, the step $h$
//! halved when Newton fails and grown after easy steps. Along the curve: folds in speed or in
//! lean (the tangent's speed or lean component changing sign) and branch points (the
//! unoriented tangent $\nabla F_1 \times \nabla F_2$ turning against the oriented one: the
//! cross product passes through zero there). Every point carries its stability with no steer
//! torque (the eigenvalues of [`super::TurnSolver::reduced_jacobian`], the family's zero set
//! aside).
//!
//! Families that meet neither upright line at a positive speed are found by
//! [`HandsFree::isolated`]: a scan of the steer torque of the turns at one lean
//! ([`SCAN_LEAN`]) over the speed, each sign change off the known families seeding a
//! continuation followed both ways ([`HandsFree::through`]).

use nalgebra::{Matrix3, Vector3};

use super::{TurnError, TurnSolver};

/// The two rows $(f_{3,1}, f_{3,2})$ at $z = (v, \varphi, \delta)$ and their gradients in $z$.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Rows {
    /// The rows (N m).
    f: [f64; 2],
    /// Row $r$'s gradient in $(v, \varphi, \delta)$.
    grad: [[f64; 3]; 2],
}

/// One point of a hands-free family.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvePoint {
    /// The rear contact's speed (m/s).
    pub speed: f64,
    /// Lean (rad).
    pub lean: f64,
    /// Steer (rad, in $(-\pi, \pi]$).
    pub steer: f64,
    /// Pitch (rad).
    pub pitch: f64,
    /// Whether the turn is stable with no steer torque: its growth below zero by more than
    /// rounding ([`MARGINAL`] times the largest eigenvalue's modulus, at least 1/s). A growth
    /// within that of zero (a branch point on upright running, where the capsize eigenvalue
    /// crosses zero) is not stable.
    pub stable: bool,
    /// The largest real part of its four eigenvalues (1/s).
    pub growth: f64,
}

/// The growth, relative to the largest eigenvalue's modulus (at least 1/s), within which of
/// zero a turn counts as marginal, not stable: far above the rounding of the eigenvalues of the
/// reduced Jacobian (1.5e-15 1/s at the benchmark's capsize branch point), far below any stable
/// turn's margin (4.3e-3 1/s at the nearest, on the reversed family near 4.58 m/s).
pub const MARGINAL: f64 = 1e-10;

/// A special point of a family: its index in [`Family::points`] (the point after it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Special {
    /// The speed turns back.
    SpeedFold(usize),
    /// The lean turns back.
    LeanFold(usize),
    /// Another family crosses.
    Branch(usize),
    /// The stability changes.
    StabilityChange(usize),
}

impl Special {
    /// The same special point at the index `f(k)`.
    fn map(self, f: impl Fn(usize) -> usize) -> Special {
        match self {
            Special::SpeedFold(k) => Special::SpeedFold(f(k)),
            Special::LeanFold(k) => Special::LeanFold(f(k)),
            Special::Branch(k) => Special::Branch(f(k)),
            Special::StabilityChange(k) => Special::StabilityChange(f(k)),
        }
    }
}

impl Family {
    /// Whether it was followed through a seed, not from a branch point on an upright line.
    pub fn is_isolated(&self) -> bool {
        self.branch_speed.is_nan()
    }
}

/// Why a family's continuation stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// The next point's speed would leave $(0,$ [`MAX_SPEED`]$]$.
    Speed,
    /// The next point's lean would reach [`MAX_LEAN`].
    Lean,
    /// The step fell below its least size (a pole of the equations, the fork across the frame,
    /// or the front contact lost).
    Stuck,
    /// The number of steps was reached.
    Steps,
}

/// A family of hands-free turns followed from a branch point, or through a seed
/// ([`HandsFree::through`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Family {
    /// The speed of the branch point on the upright line (m/s); NaN for a family followed
    /// through a seed.
    pub branch_speed: f64,
    /// The steer of the upright line (0 or π); the seed's steer for a family followed through
    /// a seed.
    pub line_steer: f64,
    /// The points, from the branch point on.
    pub points: Vec<CurvePoint>,
    /// Folds, branch points and changes of stability along it.
    pub special: Vec<Special>,
    /// Why it stopped.
    pub end: End,
}

/// The largest speed a family is followed to (m/s).
pub const MAX_SPEED: f64 = 20.0;
/// The lean at which a family stops (rad): the nonlinear model's fall angle.
pub const MAX_LEAN: f64 = 1.2;
/// The most continuation steps of a family.
pub const MAX_STEPS: usize = 2000;
/// The lean of the scan of [`HandsFree::isolated`] (rad).
pub const SCAN_LEAN: f64 = 0.3;
/// The speed step of the scan of [`HandsFree::isolated`] (m/s).
pub const SCAN_SPEED_STEP: f64 = 0.1;

/// Whether `z` $= (v, \varphi, \delta)$ lies on `family`: within $10^{-2}$ of a segment
/// between two consecutive points (the steer compared on the circle).
fn on_family(family: &Family, z: [f64; 3]) -> bool {
    let pi = std::f64::consts::PI;
    let wrap = |a: f64| (a + pi).rem_euclid(2.0 * pi) - pi;
    family.points.windows(2).any(|w| {
        let a = [w[0].speed, w[0].lean, w[0].steer];
        let d = [w[1].speed - a[0], w[1].lean - a[1], wrap(w[1].steer - a[2])];
        let r = [z[0] - a[0], z[1] - a[1], wrap(z[2] - a[2])];
        let dd: f64 = d.iter().map(|x| x * x).sum();
        let t = if dd > 0.0 {
            (r.iter().zip(&d).map(|(x, y)| x * y).sum::<f64>() / dd).clamp(0.0, 1.0)
        } else {
            0.0
        };
        r.iter().zip(&d).map(|(x, y)| (x - t * y).powi(2)).sum::<f64>() <= 1e-4
    })
}

/// The steer of the two upright lines: straight ahead (0) and the handlebar reversed (π).
pub const LINES: [f64; 2] = [0.0, std::f64::consts::PI];

/// The hands-free turns of one bicycle.
#[derive(Debug)]
pub struct HandsFree<'a> {
    solver: &'a TurnSolver,
    rr: f64,
}

impl<'a> HandsFree<'a> {
    /// The hands-free turns of the bicycle of `solver`.
    pub fn new(solver: &'a TurnSolver) -> HandsFree<'a> {
        HandsFree { solver, rr: solver.param("rR") }
    }

    /// The two rows $(f_{3,1}, f_{3,2})$ at $z = (v, \varphi, \delta)$ with their gradients
    /// in $z$ (generated, [`TurnSolver::rows`]; the speed through the rear wheel's rate
    /// $\dot\theta_R = -v/r_R$), and the pitch (solved by Newton from `guess`).
    fn rows(&self, z: [f64; 3], guess: f64) -> Option<(Rows, f64)> {
        let pitch = self.solver.bike().pitch(z[1], z[2], guess).ok()?;
        let r = self.solver.rows(z[1], pitch, z[2], -z[0] / self.rr);
        let grad = r.d.map(|[lean, steer, wheel]| [wheel * (-1.0 / self.rr), lean, steer]);
        let rows = Rows { f: r.f, grad };
        let ok = rows.f.iter().chain(rows.grad.iter().flatten()).all(|x| x.is_finite());
        ok.then_some((rows, r.pitch))
    }

    /// The determinant of the rows' Jacobian in (lean, steer) on the upright line of steer
    /// `line_steer` at `speed`.
    pub fn line_determinant(&self, speed: f64, line_steer: f64) -> Option<f64> {
        let (f, _) = self.rows([speed, 0.0, line_steer], 0.0)?;
        Some(f.grad[0][1] * f.grad[1][2] - f.grad[0][2] * f.grad[1][1])
    }

    /// The speeds in `(0, max]` (m/s) where a family branches from the upright line of steer
    /// `line_steer` (0: straight ahead, π: the handlebar reversed): the sign changes of
    /// [`line_determinant`](Self::line_determinant) on 2000 steps of speed, bisected to
    /// $10^{-14}$ relative.
    pub fn branch_speeds(&self, line_steer: f64, max: f64) -> Vec<f64> {
        let n = 2000;
        let at = |k: usize| max * k as f64 / n as f64;
        let det = |v: f64| self.line_determinant(v, line_steer);
        let mut out = Vec::new();
        let mut prev = det(at(1)).map(|d| (at(1), d));
        for k in 2..=n {
            let here = det(at(k)).map(|d| (at(k), d));
            if let (Some((a, da)), Some((b, db))) = (prev, here) {
                if da == 0.0 {
                    out.push(a);
                } else if da * db < 0.0 {
                    let (mut lo, mut hi, mut dlo) = (a, b, da);
                    while hi - lo > 1e-14 * hi {
                        let mid = 0.5 * (lo + hi);
                        match det(mid) {
                            Some(d) if (d < 0.0) == (dlo < 0.0) => {
                                lo = mid;
                                dlo = d;
                            }
                            Some(_) => hi = mid,
                            None => break,
                        }
                    }
                    out.push(0.5 * (lo + hi));
                }
            }
            prev = here;
        }
        out
    }

    /// Every family that branches from the upright [`LINES`] below [`MAX_SPEED`], in the
    /// order of the lines and, on each, of the branch speeds, then the families that meet
    /// neither line found by [`isolated`](Self::isolated).
    ///
    /// # Errors
    /// [`TurnError`] when a family has no first point off its line or the scan fails.
    pub fn families(&self) -> Result<Vec<Family>, TurnError> {
        let mut out = Vec::new();
        for line in LINES {
            for vb in self.branch_speeds(line, MAX_SPEED) {
                out.push(self.family(line, vb)?);
            }
        }
        let isolated = self.isolated(&out)?;
        out.extend(isolated);
        Ok(out)
    }

    /// The families that meet no upright line at a positive speed, found from the hands-free
    /// turns at the lean [`SCAN_LEAN`]: every turn of [`TurnSolver::turns`] at the speeds
    /// [`SCAN_SPEED_STEP`], 2 [`SCAN_SPEED_STEP`], … up to [`MAX_SPEED`] / 2, each matched to
    /// the turn of nearest steer (within 0.15 rad) at the next speed; where the steer torque
    /// changes sign between the two, a hands-free turn lies between them. One that lies on
    /// none of `known` (nor on a family found before it) seeds [`through`](Self::through).
    ///
    /// # Errors
    /// [`TurnError`] when the turns at a speed of the scan cannot be found or a seed does not
    /// converge.
    pub fn isolated(&self, known: &[Family]) -> Result<Vec<Family>, TurnError> {
        let pi = std::f64::consts::PI;
        let wrap = |a: f64| (a + pi).rem_euclid(2.0 * pi) - pi;
        let mut found: Vec<Family> = Vec::new();
        let mut prev: Option<(f64, Vec<(f64, f64)>)> = None;
        let n = (0.5 * MAX_SPEED / SCAN_SPEED_STEP).round() as usize;
        for k in 1..=n {
            let v = SCAN_SPEED_STEP * k as f64;
            let here: Vec<(f64, f64)> = self
                .solver
                .turns(v, SCAN_LEAN)?
                .turns
                .iter()
                .map(|t| (t.steer, t.steer_torque))
                .collect();
            if let Some((v0, before)) = &prev {
                for &(s1, t1) in &here {
                    let Some(&(s0, t0)) = before
                        .iter()
                        .min_by(|a, b| wrap(a.0 - s1).abs().total_cmp(&wrap(b.0 - s1).abs()))
                    else {
                        continue;
                    };
                    if wrap(s0 - s1).abs() > 0.15 || t0 * t1 >= 0.0 {
                        continue;
                    }
                    let f = t0 / (t0 - t1);
                    let seed = [v0 + f * (v - v0), SCAN_LEAN, s0 + f * wrap(s1 - s0)];
                    let Some((z, _)) = self.refine(seed) else { continue };
                    let on = |fam: &Family| on_family(fam, z);
                    if known.iter().any(on) || found.iter().any(on) {
                        continue;
                    }
                    found.push(self.through(z)?);
                }
            }
            prev = Some((v, here));
        }
        Ok(found)
    }

    /// The point at `z` with its stability with no steer torque.
    fn point(&self, z: [f64; 3], pitch: f64) -> Option<CurvePoint> {
        let mut y = [0.0; super::rate::LEN];
        y[3] = z[1];
        y[4] = z[2];
        y[9] = -z[0] / self.rr;
        y[super::rate::PITCH] = pitch;
        let a = self.solver.reduced_jacobian(&y, [0.0, 0.0]).ok()?;
        let schur = nalgebra::Schur::try_new(a, 1e-15, 10_000)?;
        let mut ev: Vec<_> = schur.complex_eigenvalues().iter().copied().collect();
        let k = (0..ev.len()).min_by(|&i, &j| ev[i].norm().total_cmp(&ev[j].norm()))?;
        ev.remove(k);
        let growth = ev.iter().map(|e| e.re).fold(f64::NEG_INFINITY, f64::max);
        let scale = ev.iter().map(|e| e.norm()).fold(1.0, f64::max);
        // The steer in (-pi, pi] (the continuation carries it unwrapped).
        let pi = std::f64::consts::PI;
        let mut steer = z[2];
        while steer > pi {
            steer -= 2.0 * pi;
        }
        while steer <= -pi {
            steer += 2.0 * pi;
        }
        let stable = growth < -MARGINAL * scale;
        Some(CurvePoint { speed: z[0], lean: z[1], steer, pitch, stable, growth })
    }

    /// The unoriented tangent $\nabla F_1\times\nabla F_2$ at `f`.
    fn cross(f: &Rows) -> Vector3<f64> {
        Vector3::from(f.grad[0]).cross(&Vector3::from(f.grad[1]))
    }

    /// Newton on $F(z) = 0$, $t\cdot(z - z_0) = h$ from `z`; the point, its rows and pitch.
    fn correct(
        &self,
        z0: Vector3<f64>,
        t: Vector3<f64>,
        h: f64,
        guess: f64,
    ) -> Option<(Vector3<f64>, Rows, f64)> {
        let mut z = z0 + h * t;
        let mut pitch = guess;
        let scale = self.solver.scale;
        for _ in 0..12 {
            let (f, p) = self.rows([z[0], z[1], z[2]], pitch)?;
            pitch = p;
            let g = Vector3::new(f.f[0], f.f[1], t.dot(&(z - z0)) - h);
            let j = Matrix3::from_rows(&[
                Vector3::from(f.grad[0]).transpose(),
                Vector3::from(f.grad[1]).transpose(),
                t.transpose(),
            ]);
            let dz = j.lu().solve(&(-g))?;
            z += dz;
            if dz.norm() <= 1e-13 * (1.0 + z.norm()) {
                let (f, p) = self.rows([z[0], z[1], z[2]], pitch)?;
                let small = f.f.iter().all(|r| r.abs() <= super::ROOT_TOLERANCE * scale);
                return small.then_some((z, f, p));
            }
        }
        None
    }

    /// The family that branches from the upright line of steer `line_steer` at the speed
    /// `branch_speed` (a root of [`branch_speeds`](Self::branch_speeds)), followed towards
    /// positive lean.
    ///
    /// # Errors
    /// [`TurnError::Solver`] when no first point off the line can be found.
    pub fn family(&self, line_steer: f64, branch_speed: f64) -> Result<Family, TurnError> {
        let fail = |reason| TurnError::Solver { reason, steer: line_steer };
        // The null vector of the stiffness in (lean, steer) at the branch point.
        let (f, _) = self
            .rows([branch_speed, 0.0, line_steer], 0.0)
            .ok_or(fail("no contact at the branch point"))?;
        let (a, b) = (f.grad[0], f.grad[1]);
        let null = if a[1].abs() + a[2].abs() >= b[1].abs() + b[2].abs() {
            (-a[2], a[1])
        } else {
            (-b[2], b[1])
        };
        let norm = null.0.hypot(null.1);
        let (dl, ds) = if null.0 >= 0.0 {
            (null.0 / norm, null.1 / norm)
        } else {
            (-null.0 / norm, -null.1 / norm)
        };
        // The first point: the lean fixed a little off the line, Newton on (speed, steer).
        let eps = 1e-3;
        let lean = eps * dl;
        let mut v = branch_speed;
        let mut steer = line_steer + eps * ds;
        let mut pitch = 0.0;
        let mut found = false;
        for _ in 0..30 {
            let Some((f, p)) = self.rows([v, lean, steer], pitch) else { break };
            pitch = p;
            let (j11, j12, j21, j22) = (f.grad[0][0], f.grad[0][2], f.grad[1][0], f.grad[1][2]);
            let det = j11 * j22 - j12 * j21;
            let dv = -(j22 * f.f[0] - j12 * f.f[1]) / det;
            let dst = -(-j21 * f.f[0] + j11 * f.f[1]) / det;
            if !(dv.is_finite() && dst.is_finite()) {
                break;
            }
            v += dv;
            steer += dst;
            if dv.abs() + dst.abs() <= 1e-13 * (1.0 + v.abs()) {
                found = true;
                break;
            }
        }
        if !found {
            return Err(fail("no first point off the upright line"));
        }
        let start = self
            .point([branch_speed, 0.0, line_steer], 0.0)
            .ok_or(fail("no stability at the branch point"))?;
        let (f, _) =
            self.rows([v, lean, steer], pitch).ok_or(fail("the first point has no contact"))?;
        let raw = Self::cross(&f);
        // Oriented towards growing lean.
        let sign = if raw[1] >= 0.0 { 1.0 } else { -1.0 };
        let first =
            self.point([v, lean, steer], pitch).ok_or(fail("no stability at the first point"))?;
        let (points, special, end) =
            self.follow(Vector3::new(v, lean, steer), pitch, sign, vec![start, first])?;
        Ok(Family { branch_speed, line_steer, points, special, end })
    }

    /// Follows a family from `z` (a hands-free point with its `pitch`, the last of `points`)
    /// along the tangent $\nabla F_1\times\nabla F_2$ times `sign`: the points, the special
    /// points and why it stopped.
    fn follow(
        &self,
        z: Vector3<f64>,
        pitch: f64,
        sign: f64,
        mut points: Vec<CurvePoint>,
    ) -> Result<(Vec<CurvePoint>, Vec<Special>, End), TurnError> {
        let fail = |reason| TurnError::Solver { reason, steer: z[2] };
        let (f, _) =
            self.rows([z[0], z[1], z[2]], pitch).ok_or(fail("the first point has no contact"))?;
        let (mut z, mut pitch, mut sign) = (z, pitch, sign);
        let mut t = sign * Self::cross(&f).normalize();
        let mut special = Vec::new();
        let (h_min, h_max) = (1e-6, 0.05);
        let mut h = 0.01;
        let mut end = End::Steps;
        for _ in 0..MAX_STEPS {
            let step = self.correct(z, t, h, pitch);
            let Some((zn, f, p)) = step else {
                h *= 0.5;
                if h < h_min {
                    end = End::Stuck;
                    break;
                }
                continue;
            };
            if zn[0] <= 0.0 || zn[0] > MAX_SPEED {
                end = End::Speed;
                break;
            }
            if zn[1].abs() >= MAX_LEAN {
                end = End::Lean;
                break;
            }
            let raw = Self::cross(&f);
            let oriented = if raw.dot(&t) >= 0.0 { 1.0 } else { -1.0 };
            let tn = oriented * raw.normalize();
            let k = points.len();
            if oriented * sign < 0.0 {
                // The cross product turned against the curve's direction: it passed zero.
                special.push(Special::Branch(k));
            }
            sign = oriented;
            if tn[0] * t[0] < 0.0 {
                special.push(Special::SpeedFold(k));
            }
            if tn[1] * t[1] < 0.0 {
                special.push(Special::LeanFold(k));
            }
            let pt =
                self.point([zn[0], zn[1], zn[2]], p).ok_or(fail("no stability on the family"))?;
            if pt.stable != points[k - 1].stable {
                special.push(Special::StabilityChange(k));
            }
            points.push(pt);
            z = zn;
            t = tn;
            pitch = p;
            h = (h * 1.5).min(h_max);
        }
        Ok((points, special, end))
    }

    /// The hands-free point nearest `seed` $= (v, \varphi, \delta)$ at its lean: Newton on
    /// (speed, steer) with the lean fixed; the point and its pitch, `None` when Newton does
    /// not converge in 30 steps.
    pub fn refine(&self, seed: [f64; 3]) -> Option<([f64; 3], f64)> {
        let [mut v, lean, mut steer] = seed;
        let mut pitch = 0.0;
        for _ in 0..30 {
            let (f, p) = self.rows([v, lean, steer], pitch)?;
            pitch = p;
            let (j11, j12, j21, j22) = (f.grad[0][0], f.grad[0][2], f.grad[1][0], f.grad[1][2]);
            let det = j11 * j22 - j12 * j21;
            let dv = -(j22 * f.f[0] - j12 * f.f[1]) / det;
            let dst = -(-j21 * f.f[0] + j11 * f.f[1]) / det;
            if !(dv.is_finite() && dst.is_finite()) {
                return None;
            }
            v += dv;
            steer += dst;
            if dv.abs() + dst.abs() <= 1e-13 * (1.0 + v.abs()) {
                return (v > 0.0).then_some(([v, lean, steer], pitch));
            }
        }
        None
    }

    /// The family through the hands-free point nearest `seed` (see [`refine`](Self::refine)),
    /// followed both ways from it: towards falling lean first (the points returned in the
    /// other order, so that the family runs towards growing lean through the seed), then
    /// towards growing lean. [`Family::branch_speed`] is NaN (no branch point) and
    /// [`Family::line_steer`] the seed's steer; [`Family::end`] is why the second half stopped.
    ///
    /// # Errors
    /// [`TurnError::Solver`] when Newton from `seed` does not converge.
    pub fn through(&self, seed: [f64; 3]) -> Result<Family, TurnError> {
        let fail = |reason| TurnError::Solver { reason, steer: seed[2] };
        let (z, pitch) = self.refine(seed).ok_or(fail("no hands-free turn near the seed"))?;
        let first = self.point(z, pitch).ok_or(fail("no stability at the seed"))?;
        let zv = Vector3::from(z);
        let (f, _) = self.rows(z, pitch).ok_or(fail("the seed has no contact"))?;
        let up = if Self::cross(&f)[1] >= 0.0 { 1.0 } else { -1.0 };
        let (mut back, back_special, _) = self.follow(zv, pitch, -up, vec![first])?;
        let (ahead, ahead_special, end) = self.follow(zv, pitch, up, vec![first])?;
        let n = back.len();
        back.reverse();
        // Indices of the backward half count from its far end; each special point marks the
        // point after it in the direction of growing lean.
        let mut special: Vec<Special> = back_special.iter().map(|s| s.map(|k| n - k)).collect();
        special.reverse();
        special.extend(ahead_special.iter().map(|s| s.map(|k| k + n - 1)));
        back.extend_from_slice(&ahead[1..]);
        Ok(Family { branch_speed: f64::NAN, line_steer: z[2], points: back, special, end })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::rng::SplitMix64;
    use crate::whipple::WhippleParams;
    use carvallo_ir::dual::Dual;

    /// The largest difference between `got` and `want` (value, then derivatives) relative to the
    /// largest entry of `want` (at least 1).
    fn relative(got: &[f64], want: &[f64]) -> f64 {
        let scale = want.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        got.iter().zip(want).map(|(g, w)| (g - w).abs() / scale).fold(0.0, f64::max)
    }

    /// The generated derivatives the Newton steps use ([`TurnSolver::rows`]: the turns'
    /// $dF/d\delta$; [`HandsFree::rows`]: the hands-free rows' gradients in speed, lean and
    /// steer) against the route they replaced, forward-mode dual numbers through the IR
    /// interpreter ([`TurnSolver::terms`], the pitch projected in dual arithmetic; no
    /// generated derivative, no chain rule written by hand), at 40 seeded states of the
    /// benchmark bicycle: speed in [0.5, 10) m/s, lean in ±0.6 rad, steer in ±1.3 rad and a
    /// quarter of them with the handlebar reversed (steer + π); the pitch on the contact
    /// constraint, then, for half of them, moved by 1e-9 rad so that the projection's
    /// second-order term $h\,h_{\theta v}$ counts. Both rows and their three derivatives agree
    /// to 1e-12 of each row's largest entry (the worst is printed with `--nocapture`).
    ///
    /// A wrong column fails it: with the pitch's part of $\mathrm{d}/\mathrm{d}\delta$ dropped
    /// from [`TurnSolver::rows`] (the constraint moves the pitch as the steer turns; tried once
    /// in a scratch run) the first state fails, $df_{3,1}/d\delta$ -3306.33 against the dual
    /// numbers' -3298.22 (2.1e-3 of the row's largest entry).
    #[test]
    fn the_generated_turn_derivatives_equal_the_dual_numbers_they_replaced() {
        let s = TurnSolver::new(&WhippleParams::benchmark()).expect("the solver");
        let hf = HandsFree::new(&s);
        let rr = s.param("rR");
        let mut rng = SplitMix64(3508);
        let (mut worst_rows, mut worst_hands_free) = (0.0f64, 0.0f64);
        for k in 0..40 {
            let speed = rng.uniform(0.5, 10.0);
            let lean = rng.uniform(-0.6, 0.6);
            let reversed = if k % 4 == 3 { std::f64::consts::PI } else { 0.0 };
            let steer = rng.uniform(-1.3, 1.3) + reversed;
            let wheel = -speed / rr;
            let on = s.bike().pitch(lean, steer, 0.0).expect("the pitch");
            // The rows in (lean, steer, rear wheel rate), on the constraint and off it.
            let pitch = if k % 2 == 0 { on } else { on + 1e-9 };
            let got = s.rows(lean, pitch, steer, wheel);
            let c = Dual::<3>::constant;
            let t = s.terms(
                Dual::variable(lean, 0),
                c(pitch),
                Dual::variable(steer, 1),
                [c(0.0), c(0.0), Dual::variable(wheel, 2)],
            );
            for r in 0..2 {
                let want = t.forcing[r];
                let err = relative(
                    &[got.f[r], got.d[r][0], got.d[r][1], got.d[r][2]],
                    &[want.value, want.grad[0], want.grad[1], want.grad[2]],
                );
                worst_rows = worst_rows.max(err);
                assert!(err <= 1e-12, "state {k}, row {r}: {got:?} vs dual numbers {want:?}");
            }
            // The hands-free rows in (speed, lean, steer), the pitch solved from `on`.
            let (got, _) = hf.rows([speed, lean, steer], on).expect("the rows");
            let solved = s.bike().pitch(lean, steer, on).expect("the pitch");
            let v = Dual::<3>::variable(speed, 0);
            let t = s.terms(
                Dual::variable(lean, 1),
                c(solved),
                Dual::variable(steer, 2),
                [c(0.0), c(0.0), v.scale(-1.0 / rr)],
            );
            for r in 0..2 {
                let want = t.forcing[r];
                let mut g = vec![got.f[r]];
                g.extend(got.grad[r]);
                let mut w = vec![want.value];
                w.extend(want.grad);
                let err = relative(&g, &w);
                worst_hands_free = worst_hands_free.max(err);
                assert!(err <= 1e-12, "state {k}, row {r}: {got:?} vs dual numbers {want:?}");
            }
        }
        eprintln!(
            "turn rows, generated vs dual numbers: worst {worst_rows:.2e} (lean, steer, wheel \
             rate), {worst_hands_free:.2e} (hands-free: speed, lean, steer) of the row's \
             largest entry; turn_rows_scene {} operations ({} derivatives of {})",
            super::super::turn_rows_scene::OP_COUNT,
            super::super::turn_rows_scene::JACOBIAN_NONZEROS,
            2 * 4
        );
    }
}
