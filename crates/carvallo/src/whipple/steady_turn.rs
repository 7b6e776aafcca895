//! Steady turns of the nonlinear Carvallo–Whipple bicycle with the handlebar held by a constant
//! torque: the memoir's chapter IV (n° 79–106, the conversions; n° 99–105 the handlebar held)
//! for any parameter set of the 2007 benchmark, not only Carvallo's own bicycle
//! ([`crate::bicycle::turn`]). Beside it: [`lean_rider`], the same for Moore's leaning rider
//! (the torso's lean one more unknown), and [`hands_free`], the turns without steer torque as
//! families followed from their branch points on upright running.
//!
//! # The turn
//!
//! In a steady turn every speed is constant: the lean rate and the steer rate vanish, the
//! independent accelerations vanish, and the configuration (lean φ, steer δ, pitch θ) is fixed
//! in the yawed frame, which turns at the yaw rate $\dot\psi$. Kane's equations
//! $M_3\dot u = f_3 + (T_\varphi, T_\delta, 0)$ (rows lean, steer, rear wheel,
//! [`super::nonlinear::inputs`]) then reduce to $f_3 + (0, T_\delta, 0) = 0$ at
//! $u = (0, 0, \dot\theta_R)$. The speed $v$ is that of the rear contact,
//! $v = -r_R(\dot\theta + \dot\theta_R)$, and the pitch rate vanishes, so $\dot\theta_R = -v/r_R$.
//! At a given $(v, \varphi)$ the pitch is a function of the steer (the front contact constraint
//! $h(\varphi, \theta, \delta) = 0$), and the roll row
//! $$F(\delta) = f_{3,1}(\varphi, \theta(\varphi, \delta), \delta;\ 0, 0, -v/r_R) = 0$$
//! is one equation in δ: every root over $(-\pi, \pi]$ is a turn. The steer row gives the torque
//! that holds the handlebar, $T_\delta = -f_{3,2}$; the rear-wheel row needs no pedal torque
//! (the steer does no work while δ is fixed and no other force works, so the kinetic energy is
//! constant), and its value at the solution, [`SteadyTurn::rear_row_residual`], is a check.
//!
//! The roots are bracketed by a scan of δ over 720 points of $(-\pi, \pi]$ (the pitch
//! continued from point to point by Newton's method on $h$), then found by Newton's method
//! safeguarded by bisection inside each bracket. The derivative $dF/d\delta$ is exact to
//! rounding: generated code ([`turn_rows_scene`]: $f_{3,1}$, $f_{3,2}$ and their derivatives
//! with respect to lean, pitch, steer and the rear wheel's rate, forward-mode differentiation
//! of `generated/whipple_nonlinear.ir` at compile time) at the pitch projected onto the
//! constraint by one Newton step, $\theta^* = \theta - h/h_\theta$, whose derivative
//! $d\theta^*/d\delta = -(h_\delta h_\theta - h\,h_{\theta\delta})/h_\theta^2$ comes from
//! the generated derivatives of the constraint
//! ([`project_jacobian_scene`](super::nonlinear::rate::project_jacobian_scene)); on the
//! constraint it is the implicit function theorem's $-h_\delta/h_\theta$; the values at a
//! turn found come from the generated kernel
//! ([`state_rate_scene`](super::nonlinear::rate::state_rate_scene)), so a turn runs no
//! interpreter. Forward-mode dual numbers through the IR interpreter ([`carvallo_ir::dual`]),
//! which computed the derivative before, remain its reference in the tests (`hands_free`'s
//! `the_generated_turn_derivatives_equal_the_dual_numbers_they_replaced`) and the reference
//! of the stability's Jacobian ([`TurnSolver::state_jacobian_dual`]). A sign change across a
//! pole of $F$ (the fork across the frame, $\delta = \pm\pi/2$, where the yaw rate grows as
//! $\tan\delta$) is not a root: a bracket is kept only when $|F|$ falls below
//! [`ROOT_TOLERANCE`] times the weight times the wheelbase.
//!
//! # Contact forces
//!
//! The generated program has no contact forces; they follow from the momentum balance of the
//! whole bicycle in the turn. Every mass centre is fixed in the yawed frame, so its
//! acceleration is $\dot\psi v\,\hat y - \dot\psi^2(r_x, r_y, 0)$ ($r$ from the rear contact $P$,
//! yawed frame, z down), and every body's angular momentum about its mass centre is constant in
//! that frame, so its rate is $\dot\psi\hat z \times H$ (the wheels too: symmetric about their
//! axles, spinning at constant rates). Each wheel spins freely on its bearing and
//! $\dot H\cdot a = 0$ for its axle $a$, so each contact force has no component along its
//! wheel's heading: a normal force $N$ and a lateral force $L$ (horizontal, perpendicular to the
//! wheel's heading; positive to the right for the rear wheel, along the front axle's horizontal
//! projection for the front one). The four unknowns $N_R, L_R, N_F, L_F$ solve the six
//! equations $F_P + F_Q = \sum_i m_i(a_i - g\hat z)$ and
//! $r_Q\times F_Q = \sum_i r_i\times m_i(a_i - g\hat z) + \dot\psi\hat z\times H_i$ by least
//! squares; the two equations too many are the lean row and the rear-wheel row of the same
//! turn, so the residual ([`ContactForces::balance_residual`]) checks the turn by a route that
//! does not use $f_3$. The positions, orientations and inertias are built here from the 25
//! parameters, not read from the program. The friction a contact demands is $|L|/N$.
//!
//! # Stability
//!
//! The turn's stability with the steer torque held constant is read from the eigenvalues of the
//! linearisation of the eleven-state right-hand side ([`StateRate`]) about it.
//! [`TurnSolver::state_jacobian`] is the one place that Jacobian comes from: the generated
//! [`StateRate::jacobian_with`]; [`TurnSolver::state_jacobian_dual`], dual numbers through the
//! same program and the same one-step projection of the pitch (the IR interpreter, no
//! generated derivative), is its reference (equal to 1e-12, `tests/it/whipple/steady_turn.rs`).
//! Its structural zero eigenvalues: the rear contact's position $(x, y)$, the yaw and the two
//! wheel angles are ignorable (no equation depends on them; the yaw enters only the rates of
//! $x$ and $y$), five zeros; the pitch is dependent (the right-hand side projects it onto the
//! constraint, so its column vanishes on the constraint), one more. What is left is the
//! $5\times5$ block of lean, steer, lean rate, steer rate and rear wheel rate, itself singular:
//! at a constant steer torque the turns form a one-parameter family (the speed varies along
//! it), and the tangent of that family is a null vector. Its eigenvalue, the one of smallest
//! modulus, is set aside ([`Stability::family`], zero to rounding) and the four others decide:
//! the turn is stable when their real parts are all negative.

use std::fmt;
use std::sync::OnceLock;

use carvallo_ir::dual::{self, Dual};
use carvallo_ir::Program;
use nalgebra::{Complex, Matrix3, SMatrix, SVector, Vector3};

use super::nonlinear::rate::{
    self, fill, filled, input_slots, project_jacobian_scene, state_rate_scene, StateRate,
};
use super::nonlinear::{Configuration, NonlinearError, WhippleNonlinear};
use super::WhippleParams;
use crate::error::ParameterError;

pub mod hands_free;
pub mod lean_rider;

crate::scene! {
    /// The lean and steer rows $f_{3,1}$, $f_{3,2}$ of Kane's equations and their derivatives
    /// with respect to the lean, the pitch, the steer and the rear wheel's rate: what the
    /// turns' Newton steps need ($dF/d\delta$, and the hands-free rows' gradients in speed,
    /// lean and steer).
    pub mod turn_rows_scene {
        model: whipple_nonlinear,
        outputs: [f3_1, f3_2],
        jacobian: [phi, theta, delta, thetaRd],
    }
}

/// The lean and steer rows $(f_{3,1}, f_{3,2})$ at a steady state (lean and steer rates zero),
/// the pitch projected onto the contact constraint by one Newton step, and their derivatives
/// along the projected pitch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rows {
    /// $(f_{3,1}, f_{3,2})$ (N m).
    pub f: [f64; 2],
    /// Row $r$ of `f`, columns $\mathrm{d}/\mathrm{d}\varphi$ and
    /// $\mathrm{d}/\mathrm{d}\delta$ (the pitch following the projection) and
    /// $\partial/\partial\dot\theta_R$.
    pub d: [[f64; 3]; 2],
    /// The projected pitch (rad).
    pub pitch: f64,
}

/// The number of steer angles of the bracketing scan over $(-\pi, \pi]$ (a half degree apart).
pub const SCAN_POINTS: usize = 720;

/// A bracket holds a root when $|F|$ at its end falls below this many times the weight times
/// the wheelbase (N m); a sign change across a pole leaves $|F|$ large.
pub const ROOT_TOLERANCE: f64 = 1e-9;

/// The state indices of the block whose eigenvalues decide the stability: lean, steer, lean
/// rate, steer rate, rear wheel rate ([`rate::LEN`] order).
pub const REDUCED: [usize; 5] = [3, 4, 7, 8, 9];

/// Why no turn could be computed (a turn that does not exist is not an error: see
/// [`Turns::turns`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TurnError {
    /// An input that cannot be used (a non-positive speed, a lean at or beyond π/2, a wheel of
    /// zero radius, a value that is not finite).
    Parameter(ParameterError),
    /// The solver failed.
    Solver {
        /// What failed, in a few lower-case words.
        reason: &'static str,
        /// The steer angle where it failed (rad).
        steer: f64,
    },
}

impl fmt::Display for TurnError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TurnError::Parameter(e) => write!(f, "{e}"),
            TurnError::Solver { reason, steer } => {
                write!(f, "the steady turn solver failed at steer {steer} rad: {reason}")
            }
        }
    }
}

impl std::error::Error for TurnError {}

impl From<ParameterError> for TurnError {
    fn from(e: ParameterError) -> TurnError {
        TurnError::Parameter(e)
    }
}

fn invalid(name: &'static str, value: f64, reason: &'static str) -> TurnError {
    TurnError::Parameter(ParameterError::InvalidParameter { name, value, reason })
}

/// The forces the ground exerts on the wheels in a steady turn (N), from the momentum balance
/// of the whole bicycle (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactForces {
    /// Normal force on the rear wheel, upwards (N).
    pub rear_normal: f64,
    /// Lateral force on the rear wheel, to the right of its heading (N).
    pub rear_lateral: f64,
    /// Normal force on the front wheel, upwards (N).
    pub front_normal: f64,
    /// Lateral force on the front wheel, horizontal and perpendicular to its heading, along
    /// the horizontal projection of its axle (to the right when the steer is zero) (N).
    pub front_lateral: f64,
    /// The friction coefficient the rear contact demands, $|L_R|/N_R$.
    pub rear_friction: f64,
    /// The friction coefficient the front contact demands, $|L_F|/N_F$.
    pub front_friction: f64,
    /// The norm of the residual of the six balance equations in the four forces (N and N m):
    /// zero to rounding when the turn satisfies the lean and rear-wheel rows.
    pub balance_residual: f64,
}

impl ContactForces {
    /// Whether both normal forces are positive: otherwise a wheel would have to be held down
    /// (the model's contacts are bilateral) and the turn is a solution of the equations that no
    /// bicycle on the ground can follow.
    pub fn on_ground(&self) -> bool {
        self.rear_normal > 0.0 && self.front_normal > 0.0
    }
}

/// The stability of a turn with the steer torque held constant: `N` eigenvalues decide (four
/// for the bicycle, six for the leaning rider).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stability<const N: usize = 4> {
    /// The eigenvalues that decide (1/s), by decreasing real part.
    pub eigenvalues: [Complex<f64>; N],
    /// The eigenvalue set aside: the family of turns at the same steer torque (zero to
    /// rounding).
    pub family: Complex<f64>,
    /// Whether every real part of [`eigenvalues`](Self::eigenvalues) is negative.
    pub stable: bool,
}

/// One steady turn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyTurn {
    /// The rear contact's speed (m/s).
    pub speed: f64,
    /// Lean φ (rad, positive to the right).
    pub lean: f64,
    /// Steer δ (rad).
    pub steer: f64,
    /// Rear frame pitch θ (rad).
    pub pitch: f64,
    /// Yaw rate $\dot\psi$ (rad/s, positive turning right).
    pub yaw_rate: f64,
    /// Radius of the rear contact's circle, $v/\dot\psi$ (m; positive turning right, infinite
    /// when the yaw rate is zero).
    pub radius: f64,
    /// The steer torque that holds the handlebar, $-f_{3,2}$ (N m).
    pub steer_torque: f64,
    /// The rear wheel's rate on the frame (rad/s).
    pub rear_wheel_rate: f64,
    /// The front wheel's rate on the fork (rad/s).
    pub front_wheel_rate: f64,
    /// The roll row $f_{3,1}$ at the solution (N m).
    pub roll_residual: f64,
    /// The rear-wheel row $f_{3,3}$ at the solution: no pedal torque is needed (N m).
    pub rear_row_residual: f64,
    /// The contact forces.
    pub forces: ContactForces,
    /// The stability with the steer torque held.
    pub stability: Stability,
}

/// Every steady turn at one speed and lean.
#[derive(Clone, Debug, PartialEq)]
pub struct Turns {
    /// The rear contact's speed (m/s).
    pub speed: f64,
    /// The lean (rad).
    pub lean: f64,
    /// The turns, by increasing steer; empty when no steer holds this lean at this speed (a
    /// result, not an error).
    pub turns: Vec<SteadyTurn>,
}

impl Turns {
    /// `turns` when there are some, `no steady turn` when there is none.
    pub fn status(&self) -> &'static str {
        if self.turns.is_empty() {
            "no steady turn"
        } else {
            "turns"
        }
    }
}

/// Checks a speed (positive) and a lean (strictly inside ±π/2).
pub(crate) fn check(speed: f64, lean: f64) -> Result<(), TurnError> {
    if !speed.is_finite() {
        return Err(invalid("speed", speed, "must be finite"));
    }
    if speed <= 0.0 {
        return Err(invalid("speed", speed, "must be positive"));
    }
    if !lean.is_finite() {
        return Err(invalid("lean", lean, "must be finite"));
    }
    if lean.abs() >= std::f64::consts::FRAC_PI_2 {
        return Err(invalid("lean", lean, "must lie strictly between -pi/2 and pi/2 rad"));
    }
    Ok(())
}

/// The roots of a turn's equation $F(\delta) = 0$ over $(-\pi, \pi]$, by increasing steer:
/// `value(steer, guess)` gives $F$ and the other unknowns solved beside it (the pitch, ...: the
/// guess for the next point), `None` where they cannot be solved; `newton(steer, guess)` gives
/// $F$, $dF/d\delta$ and those unknowns. A scan of [`SCAN_POINTS`] steers, each unknown
/// continued from the neighbouring point outward from zero steer, brackets the sign changes;
/// Newton's method safeguarded by bisection refines each, kept when $|F| \le$ `tolerance`
/// at its end (a pole leaves $|F|$ large).
pub(crate) fn steer_roots<G: Copy>(
    value: &dyn Fn(f64, G) -> Option<(f64, G)>,
    newton: &dyn Fn(f64, G) -> Option<(f64, f64, G)>,
    start: G,
    tolerance: f64,
) -> Vec<(f64, G)> {
    let pi = std::f64::consts::PI;
    let n = SCAN_POINTS;
    let steer_at = |k: usize| -pi + 2.0 * pi * k as f64 / n as f64;
    // Values at k = 1..=n (steer in (-pi, pi]), continued outward from zero steer.
    let mut values: Vec<Option<(f64, G)>> = vec![None; n + 1];
    let half = n / 2;
    for range in [(half..=n).collect::<Vec<_>>(), (1..half).rev().collect()] {
        let mut guess = values[half].map_or(start, |v| v.1);
        for k in range {
            values[k] = value(steer_at(k), guess);
            if let Some((_, g)) = values[k] {
                guess = g;
            }
        }
    }
    let mut roots: Vec<(f64, G)> = Vec::new();
    for k in 1..=n {
        // The pair (k, k + 1), the last wrapping round to k = 1 at steer + 2 pi.
        let (next, shift) = if k == n { (1, 2.0 * pi) } else { (k + 1, 0.0) };
        let (Some((fa, ga)), Some((fb, _))) = (values[k], values[next]) else { continue };
        if fa == 0.0 {
            roots.push((steer_at(k), ga));
        } else if fa * fb < 0.0 {
            let (a, b) = (steer_at(k), steer_at(next) + shift);
            if let Some((x, g)) = refine(newton, (a, fa), b, ga, tolerance) {
                // Normalised to (-pi, pi]; a root at pi itself may land a rounding above.
                let s = if x > pi + 1e-12 { x - 2.0 * pi } else { x.min(pi) };
                roots.push((s, g));
            }
        }
    }
    roots.sort_by(|a, b| a.0.total_cmp(&b.0));
    roots
}

/// The root of $F$ in the bracket `[a, b]` ($F(a) = $ `fa`) by Newton's method safeguarded by
/// bisection; `None` when the bracket holds a pole, not a root.
fn refine<G: Copy>(
    newton: &dyn Fn(f64, G) -> Option<(f64, f64, G)>,
    (mut a, mut fa): (f64, f64),
    mut b: f64,
    guess: G,
    tolerance: f64,
) -> Option<(f64, G)> {
    let mut x = 0.5 * (a + b);
    let mut guess = guess;
    for _ in 0..200 {
        let (f, df, g) = newton(x, guess)?;
        guess = g;
        if f == 0.0 {
            break;
        }
        if (f < 0.0) == (fa < 0.0) {
            a = x;
            fa = f;
        } else {
            b = x;
        }
        let step_to = x - f / df;
        let next = if step_to.is_finite() && step_to > a.min(b) && step_to < a.max(b) {
            step_to
        } else {
            0.5 * (a + b)
        };
        let step = next - x;
        x = next;
        if step.abs() <= 1e-15 * (1.0 + x.abs()) || (b - a).abs() <= 1e-15 * (1.0 + x.abs()) {
            break;
        }
    }
    let (f, _, g) = newton(x, guess)?;
    (f.abs() <= tolerance).then_some((x, g))
}

/// The programs the dual numbers run (the reference route,
/// [`TurnSolver::state_jacobian_dual`]): the contact constraint, and the dynamics.
struct Programs {
    contact: Program,
    dynamics: Program,
}

/// The outputs of [`Programs::dynamics`], in order: those of the right-hand side's kernel.
const DYNAMICS: &[&str] = rate::state_rate_scene::OUTPUTS;

fn programs() -> &'static Programs {
    static P: OnceLock<Programs> = OnceLock::new();
    P.get_or_init(|| {
        let p = Program::parse(crate::artifacts::WHIPPLE_NONLINEAR.ir)
            .expect("the committed program parses");
        Programs {
            contact: p
                .select_outputs(&["contact_height", "contact_height_dtheta"])
                .expect("the program has the contact constraint"),
            dynamics: p.select_outputs(DYNAMICS).expect("the program has the dynamics"),
        }
    })
}

/// The parameter values of `p` in its order, and where each of the six inputs `phi`, `theta`,
/// `delta`, `phid`, `deltad`, `thetaRd` sits among its inputs.
fn arguments(p: &Program, params: &WhippleParams) -> (Vec<f64>, [Option<usize>; 6]) {
    const NAMES: [&str; 6] = ["phi", "theta", "delta", "phid", "deltad", "thetaRd"];
    let values = p.params.iter().map(|n| params.get(n).unwrap_or(f64::NAN)).collect();
    let slots = NAMES.map(|n| p.inputs.iter().position(|i| i == n));
    (values, slots)
}

/// One program ready for dual evaluation with one bicycle's parameters.
struct DualProgram {
    program: &'static Program,
    params: Vec<f64>,
    slots: [Option<usize>; 6],
}

impl DualProgram {
    fn new(program: &'static Program, params: &WhippleParams) -> DualProgram {
        let (params, slots) = arguments(program, params);
        DualProgram { program, params, slots }
    }

    /// The outputs at the six inputs (dual).
    fn eval<const N: usize>(&self, x: [Dual<N>; 6]) -> Vec<Dual<N>> {
        let params: Vec<Dual<N>> = self.params.iter().map(|v| Dual::constant(*v)).collect();
        let mut inputs = vec![Dual::constant(0.0); self.program.inputs.len()];
        for (slot, v) in self.slots.iter().zip(x) {
            if let Some(k) = slot {
                inputs[*k] = v;
            }
        }
        dual::eval(self.program, &params, &inputs).expect("the committed program evaluates")
    }
}

/// The steady turns of one bicycle.
pub struct TurnSolver {
    bike: WhippleNonlinear,
    rate: StateRate,
    contact: DualProgram,
    dynamics: DualProgram,
    /// [`turn_rows_scene`]'s arguments with the parameters, and the slots of its inputs
    /// ([`input_slots`]).
    rows: ([f64; turn_rows_scene::Args::LEN], [usize; 6]),
    /// The same for [`project_jacobian_scene`].
    contact_jacobian: ([f64; project_jacobian_scene::Args::LEN], [usize; 6]),
    /// The same for [`state_rate_scene`].
    values: ([f64; state_rate_scene::Args::LEN], [usize; 6]),
    /// Weight times wheelbase (N m), the scale of the roll row.
    scale: f64,
}

impl fmt::Debug for TurnSolver {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TurnSolver").field("params", self.bike.params()).finish()
    }
}

/// The evaluated terms of the dynamics at one (dual) state.
struct Terms<const N: usize> {
    /// $M_3$ as `[m11, m12, m13, m22, m23, m33]`.
    mass: [Dual<N>; 6],
    /// $f_3$.
    forcing: [Dual<N>; 3],
    /// Pitch, yaw, front wheel rates and the rear contact's speed.
    rates: [Dual<N>; 4],
}

impl TurnSolver {
    /// The solver for the bicycle `params`.
    ///
    /// # Errors
    /// [`TurnError::Parameter`] naming `rR` or `rF` when a wheel has zero radius (the
    /// two-mass-skate's limit exists only in the linearised model).
    pub fn new(params: &WhippleParams) -> Result<TurnSolver, TurnError> {
        let bike = WhippleNonlinear::new(params.clone());
        bike.initial_state(1.0, 0.0).map_err(|e| match e {
            NonlinearError::Parameter(p) => TurnError::Parameter(p),
            _ => invalid("rR", f64::NAN, "the nonlinear model cannot be built"),
        })?;
        let p = programs();
        let get = |n: &str| params.get(n).unwrap_or(f64::NAN);
        let mass = get("mR") + get("mB") + get("mH") + get("mF");
        Ok(TurnSolver {
            rate: StateRate::new(params),
            contact: DualProgram::new(&p.contact, params),
            dynamics: DualProgram::new(&p.dynamics, params),
            rows: (
                filled(params, turn_rows_scene::PARAMS),
                input_slots(turn_rows_scene::PARAMS, turn_rows_scene::INPUTS),
            ),
            contact_jacobian: (
                filled(params, project_jacobian_scene::PARAMS),
                input_slots(project_jacobian_scene::PARAMS, project_jacobian_scene::INPUTS),
            ),
            values: (
                filled(params, state_rate_scene::PARAMS),
                input_slots(state_rate_scene::PARAMS, state_rate_scene::INPUTS),
            ),
            scale: mass * get("g") * get("w"),
            bike,
        })
    }

    /// The nonlinear bicycle.
    pub fn bike(&self) -> &WhippleNonlinear {
        &self.bike
    }

    fn param(&self, name: &str) -> f64 {
        self.bike.params().get(name).unwrap_or(f64::NAN)
    }

    /// The terms at lean, pitch (projected onto the contact constraint by one Newton step, as
    /// [`StateRate::project`] does when the pitch is on it), steer and the three speeds, in dual
    /// numbers through the IR interpreter: the reference route of
    /// [`state_jacobian_dual`](Self::state_jacobian_dual) and of the tests.
    fn terms<const N: usize>(
        &self,
        lean: Dual<N>,
        pitch: Dual<N>,
        steer: Dual<N>,
        u: [Dual<N>; 3],
    ) -> Terms<N> {
        let zero = Dual::constant(0.0);
        let h = self.contact.eval([lean, pitch, steer, zero, zero, zero]);
        let pitch = pitch - h[0] / h[1];
        let o = self.dynamics.eval([lean, pitch, steer, u[0], u[1], u[2]]);
        Terms {
            mass: [o[0], o[1], o[2], o[3], o[4], o[5]],
            forcing: [o[6], o[7], o[8]],
            rates: [o[9], o[10], o[11], o[12]],
        }
    }

    /// The right-hand side of [`StateRate::rates_with`] at a dual state, with the constant
    /// roll and steer torques `torque`.
    fn rhs_dual<const N: usize>(
        &self,
        y: &[Dual<N>; rate::LEN],
        torque: [f64; 2],
    ) -> [Dual<N>; rate::LEN] {
        let t = self.terms(y[3], y[rate::PITCH], y[4], [y[7], y[8], y[9]]);
        let [f1, f2, f3] = t.forcing;
        let forcing = [f1 + Dual::constant(torque[0]), f2 + Dual::constant(torque[1]), f3];
        let ud = rate::solve_symmetric_in(t.mass, forcing);
        let [thetad, psid, thetafd, speed] = t.rates;
        [
            speed * y[2].cos(),
            speed * y[2].sin(),
            psid,
            y[7],
            y[8],
            y[9],
            thetafd,
            ud[0],
            ud[1],
            ud[2],
            thetad,
        ]
    }

    /// The Jacobian $\partial\dot y/\partial y$ of [`StateRate::rates_with`] at `y` (its state
    /// order) with the constant roll and steer torques `torque` $(T_\varphi, T_\delta)$ (N m):
    /// the generated one, [`StateRate::jacobian_with`] (`scene!` Jacobians of $M_3$, $f_3$, the
    /// dependent rates and the contact constraint, the chain rule through the pitch's projection
    /// and the solve). The torques enter through $M_3^{-1}$:
    /// $\partial(M_3^{-1}(f_3 + \tau))/\partial y$ depends on τ wherever $M_3$ depends on the
    /// configuration. This is the one function the steady turns take their linearisation
    /// from; [`state_jacobian_dual`](Self::state_jacobian_dual) is its reference.
    ///
    /// # Errors
    /// [`NonlinearError`] as [`StateRate::rates_with`] (no contact, a singular mass matrix).
    pub fn state_jacobian(
        &self,
        y: &[f64; rate::LEN],
        torque: [f64; 2],
    ) -> Result<[[f64; rate::LEN]; rate::LEN], NonlinearError> {
        self.rate.jacobian_with(y, torque)
    }

    /// [`state_jacobian`](Self::state_jacobian) by forward-mode dual numbers through
    /// `generated/whipple_nonlinear.ir` (the IR interpreter, no generated derivative) and the
    /// same one-step projection of the pitch: exact to rounding, the reference the generated
    /// Jacobian is checked against. `y`'s pitch must lie on the contact constraint.
    pub fn state_jacobian_dual(
        &self,
        y: &[f64; rate::LEN],
        torque: [f64; 2],
    ) -> [[f64; rate::LEN]; rate::LEN] {
        let x: [Dual<{ rate::LEN }>; rate::LEN] = std::array::from_fn(|k| Dual::variable(y[k], k));
        let d = self.rhs_dual(&x, torque);
        std::array::from_fn(|i| d[i].grad)
    }

    /// [`Rows`] at `(lean, pitch, steer)` with the rear wheel's rate `wheel` and the lean and
    /// steer rates zero, the pitch first projected onto the contact constraint by one Newton
    /// step, $\theta^* = \theta - h/h_\theta$ (as [`terms`](Self::terms) does): generated
    /// values and derivatives ([`turn_rows_scene`], [`project_jacobian_scene`]), with
    /// $\mathrm{d}\theta^*/\mathrm{d}v = -(h_v h_\theta - h\,h_{\theta v})/h_\theta^2$ for
    /// $v$ the lean or the steer.
    pub(crate) fn rows(&self, lean: f64, pitch: f64, steer: f64, wheel: f64) -> Rows {
        let (args, slots) = &self.contact_jacobian;
        let o = project_jacobian_scene::eval_array(&fill(*args, slots, [lean, pitch, steer]));
        // Rows h, h_theta; columns lean, pitch, steer.
        let hd = project_jacobian_scene::jacobian_array(&o);
        let (h, dh) = (o[0], o[1]);
        let projected = pitch - h / dh;
        let dproj = |k: usize| -(hd[0][k] * dh - h * hd[1][k]) / (dh * dh);
        let (lean_proj, steer_proj) = (dproj(0), dproj(2));
        let (args, slots) = &self.rows;
        let o = turn_rows_scene::eval_array(&fill(
            *args,
            slots,
            [lean, projected, steer, 0.0, 0.0, wheel],
        ));
        // Columns lean, pitch, steer, rear wheel rate.
        let j = turn_rows_scene::jacobian_array(&o);
        Rows {
            f: [o[0], o[1]],
            d: std::array::from_fn(|r| {
                [j[r][0] + j[r][1] * lean_proj, j[r][2] + j[r][1] * steer_proj, j[r][3]]
            }),
            pitch: projected,
        }
    }

    /// The roll row $F(\delta)$ at `(speed, lean)`, its derivative in δ (the pitch following the
    /// constraint) and the pitch, the pitch solved by Newton from `guess`.
    fn roll_row(
        &self,
        speed: f64,
        lean: f64,
        steer: f64,
        guess: f64,
    ) -> Result<(f64, f64, f64), NonlinearError> {
        let pitch = self.bike.pitch(lean, steer, guess)?;
        let r = self.rows(lean, pitch, steer, -speed / self.param("rR"));
        Ok((r.f[0], r.d[0][1], r.pitch))
    }

    /// The roll row alone, by the generated evaluator (the scan).
    fn roll_value(&self, speed: f64, lean: f64, steer: f64, guess: f64) -> Option<(f64, f64)> {
        let pitch = self.bike.pitch(lean, steer, guess).ok()?;
        let c = Configuration {
            lean,
            pitch,
            steer,
            lean_rate: 0.0,
            steer_rate: 0.0,
            rear_wheel_rate: -speed / self.param("rR"),
        };
        let f = self.bike.kane_terms(&c).forcing[0];
        f.is_finite().then_some((f, pitch))
    }

    /// Every steady turn at the rear contact's speed `speed` (m/s) and the lean `lean` (rad),
    /// by increasing steer.
    ///
    /// # Errors
    /// [`TurnError::Parameter`] naming a speed that is not positive and finite or a lean not
    /// strictly inside ±π/2; [`TurnError::Solver`] when a turn is found but its stability
    /// cannot be computed.
    pub fn turns(&self, speed: f64, lean: f64) -> Result<Turns, TurnError> {
        check(speed, lean)?;
        let roots = steer_roots(
            &|steer, pitch| self.roll_value(speed, lean, steer, pitch),
            &|steer, pitch| self.roll_row(speed, lean, steer, pitch).ok(),
            0.0,
            ROOT_TOLERANCE * self.scale,
        );
        let turns = roots
            .into_iter()
            .map(|(steer, pitch)| self.turn_at(speed, lean, steer, pitch))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Turns { speed, lean, turns })
    }

    /// The turn at a root `(steer, pitch)` with everything measured.
    fn turn_at(
        &self,
        speed: f64,
        lean: f64,
        steer: f64,
        pitch: f64,
    ) -> Result<SteadyTurn, TurnError> {
        let wheel = -speed / self.param("rR");
        // The pitch projected by one Newton step, then the values of the generated kernel.
        let (h, dh) = self.rate.contact(lean, pitch, steer);
        let pitch = pitch - h / dh;
        let (args, slots) = &self.values;
        let o = state_rate_scene::eval_array(&fill(
            *args,
            slots,
            [lean, pitch, steer, 0.0, 0.0, wheel],
        ));
        let (yaw_rate, front_wheel_rate) = (o[10], o[11]);
        let forcing = [o[6], o[7], o[8]];
        let forces =
            self.contact_forces(lean, pitch, steer, speed, yaw_rate, wheel, front_wheel_rate);
        let mut y = [0.0; rate::LEN];
        y[3] = lean;
        y[4] = steer;
        y[9] = wheel;
        y[rate::PITCH] = pitch;
        let stability = self.stability(&y, -forcing[1]).ok_or(TurnError::Solver {
            reason: "the eigenvalues of the linearisation did not converge",
            steer,
        })?;
        Ok(SteadyTurn {
            speed,
            lean,
            steer,
            pitch,
            yaw_rate,
            radius: speed / yaw_rate,
            steer_torque: -forcing[1],
            rear_wheel_rate: wheel,
            front_wheel_rate,
            roll_residual: forcing[0],
            rear_row_residual: forcing[2],
            forces,
            stability,
        })
    }

    /// The $5\times5$ block of [`state_jacobian`](Self::state_jacobian) at `y` over
    /// [`REDUCED`] (lean, steer, lean rate, steer rate, rear wheel rate).
    ///
    /// # Errors
    /// As [`state_jacobian`](Self::state_jacobian).
    pub fn reduced_jacobian(
        &self,
        y: &[f64; rate::LEN],
        torque: [f64; 2],
    ) -> Result<SMatrix<f64, 5, 5>, NonlinearError> {
        let j = self.state_jacobian(y, torque)?;
        Ok(SMatrix::from_fn(|r, c| j[REDUCED[r]][REDUCED[c]]))
    }

    /// The stability at the turn state `y` held by the steer torque `steer_torque`; `None` when
    /// the Schur iteration does not converge.
    fn stability(&self, y: &[f64; rate::LEN], steer_torque: f64) -> Option<Stability> {
        let a = self.reduced_jacobian(y, [0.0, steer_torque]).ok()?;
        let schur = nalgebra::Schur::try_new(a, 1e-15, 10_000)?;
        let mut ev: Vec<Complex<f64>> = schur.complex_eigenvalues().iter().copied().collect();
        let k = (0..ev.len()).min_by(|&i, &j| ev[i].norm().total_cmp(&ev[j].norm()))?;
        let family = ev.remove(k);
        ev.sort_by(|a, b| b.re.total_cmp(&a.re).then(b.im.total_cmp(&a.im)));
        let eigenvalues: [Complex<f64>; 4] = ev.try_into().ok()?;
        let stable = eigenvalues.iter().all(|e| e.re < 0.0);
        Some(Stability { eigenvalues, family, stable })
    }

    /// The contact forces of the turn from the momentum balance (see the [module docs](self)).
    #[allow(clippy::too_many_arguments)]
    fn contact_forces(
        &self,
        lean: f64,
        pitch: f64,
        steer: f64,
        speed: f64,
        yaw_rate: f64,
        rear_wheel_rate: f64,
        front_wheel_rate: f64,
    ) -> ContactForces {
        let p = |n: &str| self.param(n);
        let rot_x = |a: f64| {
            let (s, c) = a.sin_cos();
            Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
        };
        let rot_y = |a: f64| {
            let (s, c) = a.sin_cos();
            Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
        };
        let rot_z = |a: f64| {
            let (s, c) = a.sin_cos();
            Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
        };
        let lambda = p("lambda");
        let (rr, rf) = (p("rR"), p("rF"));
        let rb = rot_x(lean) * rot_y(pitch);
        let rh = rb * rot_y(lambda) * rot_z(steer) * rot_y(-lambda);
        let rear_centre = rot_x(lean) * Vector3::new(0.0, 0.0, -rr);
        let a0 = Vector3::new(p("w") + p("c"), 0.0, rr);
        let axis_point = rear_centre + rb * a0;
        let frame_b = rear_centre + rb * Vector3::new(p("xB"), 0.0, p("zB") + rr);
        let frame_h = axis_point + rh * (Vector3::new(p("xH"), 0.0, p("zH") + rr) - a0);
        let front_centre = axis_point + rh * (Vector3::new(p("w"), 0.0, rr - rf) - a0);
        let rear_axle = rb * Vector3::y();
        let front_axle = rh * Vector3::y();
        let nf = (1.0 - front_axle.z * front_axle.z).sqrt();
        let down =
            Vector3::new(-front_axle.z * front_axle.x / nf, -front_axle.z * front_axle.y / nf, nf);
        let front_contact = front_centre + rf * down;
        let omega = Vector3::new(0.0, 0.0, yaw_rate);
        let frame = |i: Matrix3<f64>, r: Matrix3<f64>| r * i * r.transpose() * omega;
        let wheel = |ixx: f64, iyy: f64, axle: Vector3<f64>, spin: f64| {
            let w = omega + spin * axle;
            ixx * w + (iyy - ixx) * w.dot(&axle) * axle
        };
        let ib =
            Matrix3::new(p("IBxx"), 0.0, p("IBxz"), 0.0, p("IByy"), 0.0, p("IBxz"), 0.0, p("IBzz"));
        let ih =
            Matrix3::new(p("IHxx"), 0.0, p("IHxz"), 0.0, p("IHyy"), 0.0, p("IHxz"), 0.0, p("IHzz"));
        let bodies = [
            (p("mR"), rear_centre, wheel(p("IRxx"), p("IRyy"), rear_axle, rear_wheel_rate)),
            (p("mB"), frame_b, frame(ib, rb)),
            (p("mH"), frame_h, frame(ih, rh)),
            (p("mF"), front_centre, wheel(p("IFxx"), p("IFyy"), front_axle, front_wheel_rate)),
        ];
        let g = p("g");
        let mut force = Vector3::zeros();
        let mut moment = Vector3::zeros();
        for (m, r, h) in bodies {
            let acc = Vector3::new(
                -yaw_rate * yaw_rate * r.x,
                yaw_rate * speed - yaw_rate * yaw_rate * r.y,
                0.0,
            );
            let f = m * (acc - g * Vector3::z());
            force += f;
            moment += r.cross(&f) + omega.cross(&h);
        }
        let horizontal = (front_axle.x * front_axle.x + front_axle.y * front_axle.y).sqrt();
        let side = Vector3::new(front_axle.x / horizontal, front_axle.y / horizontal, 0.0);
        let up = -Vector3::z();
        let columns = [
            (up, Vector3::zeros()),
            (Vector3::y(), Vector3::zeros()),
            (up, front_contact.cross(&up)),
            (side, front_contact.cross(&side)),
        ];
        let a = SMatrix::<f64, 6, 4>::from_fn(|r, c| {
            let (f, m) = columns[c];
            if r < 3 {
                f[r]
            } else {
                m[r - 3]
            }
        });
        let b = SVector::<f64, 6>::from_fn(|r, _| if r < 3 { force[r] } else { moment[r - 3] });
        let x = a
            .svd(true, true)
            .solve(&b, 1e-14)
            .unwrap_or_else(|_| SVector::<f64, 4>::repeat(f64::NAN));
        let balance_residual = (a * x - b).norm();
        ContactForces {
            rear_normal: x[0],
            rear_lateral: x[1],
            front_normal: x[2],
            front_lateral: x[3],
            rear_friction: x[1].abs() / x[0],
            front_friction: x[3].abs() / x[2],
            balance_residual,
        }
    }
}

/// Every steady turn of the bicycle `params` at `speed` and `lean` ([`TurnSolver::turns`]).
///
/// # Errors
/// As [`TurnSolver::new`] and [`TurnSolver::turns`].
pub fn steady_turns(params: &WhippleParams, speed: f64, lean: f64) -> Result<Turns, TurnError> {
    TurnSolver::new(params)?.turns(speed, lean)
}
