//! Steady turns of Moore's (2012) leaning rider ([`crate::whipple::lean_rider`]): the bicycle's
//! steady turns ([`super`], memoir ch. IV n° 79–106) with the torso's lean on its joint, $q_9$,
//! one more unknown. The memoir's n° 97–98 displace the rider's centre of gravity sideways by
//! hand; here the torso finds its own equilibrium under gravity, the turn's centrifugal field
//! and the joint's spring.
//!
//! At the rear contact's speed $v$ and the roll $q_4$, with every speed but the rear wheel's
//! zero ($u_4 = u_7 = u_9 = 0$, $u_6 = -v/r_R$) and every acceleration zero, Kane's equations
//! $M\dot u = f + (T_4, T_6, T_7, T_9)$ (rows roll, rear wheel, steer, lean joint;
//! `generated/lean_rider.ir`, the spring $-k_9 q_9$ in $f$) ask for: no roll torque,
//! $f_{q_4} = 0$; no lean torque, $f_{q_9} = 0$ (the torso in equilibrium on its joint,
//! $T_9 = 0$); the steer torque $T_7 = -f_{q_7}$ that holds the handlebar; and no rear wheel
//! torque, $f_{q_6} = 0$, which holds by itself (no force works in a steady turn) and is
//! reported as a check. At each steer the pitch $q_5$ solves the front contact constraint and
//! the torso's lean solves $f_{q_9} = 0$ (Newton from the neighbouring steer's, so the torso
//! stays on the branch that starts upright); the roll row
//! $F(q_7) = f_{q_4}(q_4, q_5(q_7), q_7, q_9(q_7))$ is then scanned and refined as the
//! bicycle's (a scan of the steer and a safeguarded Newton), with
//! $dF/dq_7 = \partial_7 f_{q_4} - \partial_9 f_{q_4}\,\partial_7 f_{q_9}/\partial_9 f_{q_9}$
//! (the implicit function theorem on the torso's equation, the pitch's derivative by the same
//! theorem on the constraint). The torso's Newton steps and $dF/dq_7$ take their derivatives
//! from generated code ([`turn_rows_scene`]: $f_{q_4}$, $f_{q_9}$ and their derivatives with
//! respect to pitch, steer and torso lean; the contact constraint's from
//! [`LeanRider::contact_derivatives`]); forward-mode dual numbers through the IR interpreter,
//! which they replaced, remain their reference in the tests.
//!
//! The stability with the steer torque held: the eigenvalues of the Jacobian of the thirteen-
//! component right-hand side of [`LeanRider::rate`] (the pitch projected onto the constraint
//! as its simulation does; the generated [`LeanRider::jacobian`], dual numbers through the
//! interpreter as its reference) on roll, steer, torso lean and their rates and the rear wheel's
//! rate, seven components; the zero of the family of turns at the same torque set aside, six
//! remain. The positions, the yaw, the wheel angles are ignorable and the pitch dependent, as
//! for the bicycle. The contact forces are not computed for the rider: the momentum balance
//! of [`super`] needs every body's mass centre and inertia in the rider's axes, which the
//! program does not give.

use carvallo_ir::dual::{self, Dual};
use carvallo_ir::Program;
use nalgebra::{Complex, SMatrix};
use std::sync::OnceLock;

use super::{check, steer_roots, Stability, TurnError, ROOT_TOLERANCE};
use crate::whipple::lean_rider::{self as rider, dynamics_scene, Joint, LeanRider, PITCH};

crate::scene! {
    /// The roll row $f_{q_4}$ and the lean joint's row $f_{q_9}$ of Kane's equations and their
    /// derivatives with respect to pitch, steer and the torso's lean: what the steady turn's
    /// Newton steps need (the torso's equilibrium, $dF/dq_7$).
    pub mod turn_rows_scene {
        model: lean_rider,
        outputs: [f_q4d, f_q9d],
        jacobian: [q5, q7, q9],
    }
}

/// $f_{q_4}$ and $f_{q_9}$ at a steady state, the pitch projected by one Newton step, and
/// their derivatives along the projected pitch.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Rows {
    /// $(f_{q_4}, f_{q_9})$ (N m).
    f: [f64; 2],
    /// Row $r$ of `f`, columns $\mathrm{d}/\mathrm{d}q_7$ (the pitch following the
    /// projection) and $\partial/\partial q_9$.
    d: [[f64; 2]; 2],
    /// The projected pitch (rad).
    pitch: f64,
}

/// The state indices of the block whose eigenvalues decide: roll $q_4$, steer $q_7$, torso
/// lean $q_9$, their rates $u_4$, $u_7$, $u_9$ and the rear wheel's rate $u_6$ (Moore's order).
pub const REDUCED: [usize; 7] = [3, 5, 7, 8, 9, 10, 11];

/// The program's inputs in the order the evaluations give them.
const INPUTS: [&str; 12] =
    ["q4", "q5", "q7", "q9", "q4d", "q6d", "q7d", "q9d", "T4", "T6", "T7", "T9"];

/// One steady turn of the leaning rider.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RiderTurn {
    /// The rear contact's speed (m/s).
    pub speed: f64,
    /// Roll $q_4$ (rad, Moore's sign).
    pub lean: f64,
    /// Steer $q_7$ (rad).
    pub steer: f64,
    /// The torso's lean on its joint $q_9$ (rad).
    pub torso_lean: f64,
    /// Rear frame pitch $q_5$ (rad).
    pub pitch: f64,
    /// Yaw rate $\dot q_3$ (rad/s).
    pub yaw_rate: f64,
    /// Radius of the rear contact's circle, $v/\dot q_3$ (m; infinite when straight).
    pub radius: f64,
    /// The steer torque $T_7 = -f_{q_7}$ that holds the handlebar (N m).
    pub steer_torque: f64,
    /// The rear wheel's rate $u_6$ (rad/s).
    pub rear_wheel_rate: f64,
    /// The roll row $f_{q_4}$ at the solution (N m).
    pub roll_residual: f64,
    /// The lean joint's row $f_{q_9}$ at the solution (N m).
    pub torso_residual: f64,
    /// The rear wheel's row $f_{q_6}$ at the solution: no pedal torque is needed (N m).
    pub rear_row_residual: f64,
    /// The stability with the steer torque held: six eigenvalues.
    pub stability: Stability<6>,
}

/// Every steady turn of the leaning rider at one speed and roll.
#[derive(Clone, Debug, PartialEq)]
pub struct RiderTurns {
    /// The rear contact's speed (m/s).
    pub speed: f64,
    /// The roll (rad).
    pub lean: f64,
    /// The turns by increasing steer; empty when none exists (a result, not an error).
    pub turns: Vec<RiderTurn>,
}

impl RiderTurns {
    /// `turns` when there are some, `no steady turn` when there is none.
    pub fn status(&self) -> &'static str {
        if self.turns.is_empty() {
            "no steady turn"
        } else {
            "turns"
        }
    }
}

struct Programs {
    contact: Program,
    dynamics: Program,
}

fn programs() -> &'static Programs {
    static P: OnceLock<Programs> = OnceLock::new();
    P.get_or_init(|| {
        let p = rider::program();
        Programs {
            contact: p
                .select_outputs(&["F_contact_height", "F_contact_height_dq5"])
                .expect("the program has the contact constraint"),
            dynamics: p
                .select_outputs(dynamics_scene::OUTPUTS)
                .expect("the program has the dynamics"),
        }
    })
}

/// Whether the mass matrix $M$ (the first ten of [`dynamics_scene`]'s outputs `o`) is
/// singular to working precision: a pivot of its Gaussian elimination not above $10^{-10}$ of
/// its largest diagonal entry (a coordinate without inertia, e.g. a torso whose mass centre
/// lies on its lean axis with no moment about it). The accelerations are then not defined, and
/// the rounding errors of $M^{-1}$ would reach the eigenvalues.
fn mass_matrix_is_singular(o: &[f64; 19]) -> bool {
    const AT: [[usize; 4]; 4] = [[0, 1, 2, 3], [1, 4, 5, 6], [2, 5, 7, 8], [3, 6, 8, 9]];
    let mut m = AT.map(|row| row.map(|k| o[k]));
    let largest = (0..4).map(|k| m[k][k].abs()).fold(0.0, f64::max);
    for k in 0..4 {
        let pivot = m[k][k];
        // Not above the bound, or NaN.
        if pivot.is_nan() || pivot <= 1e-10 * largest {
            return true;
        }
        let row = m[k];
        for other in m.iter_mut().skip(k + 1) {
            let r = other[k] / pivot;
            for (x, p) in other.iter_mut().zip(row).skip(k) {
                *x -= r * p;
            }
        }
    }
    false
}

/// The steady turns of one leaning rider.
pub struct RiderTurnSolver<'a> {
    rider: &'a LeanRider,
    contact: (Vec<f64>, Vec<usize>),
    dynamics: (Vec<f64>, Vec<usize>),
    /// [`turn_rows_scene`]'s arguments with the parameters, and the slots of its inputs in
    /// [`INPUTS`] order (`usize::MAX` where it does not take one).
    rows: ([f64; turn_rows_scene::Args::LEN], [usize; 12]),
    rr: f64,
    scale: f64,
}

/// The parameter values of `p` and, for each of its inputs, its position in [`INPUTS`].
fn arguments(p: &Program, r: &LeanRider) -> (Vec<f64>, Vec<usize>) {
    let values = p
        .params
        .iter()
        .map(|n| if n == "lam" { r.upright_pitch() } else { r.params().get(n).unwrap_or(f64::NAN) })
        .collect();
    let slots = p
        .inputs
        .iter()
        .map(|n| INPUTS.iter().position(|m| m == n).expect("an input of the model"))
        .collect();
    (values, slots)
}

fn eval<const N: usize>(
    p: &Program,
    (params, slots): &(Vec<f64>, Vec<usize>),
    x: &[Dual<N>; 12],
) -> Vec<Dual<N>> {
    let params: Vec<Dual<N>> = params.iter().map(|v| Dual::constant(*v)).collect();
    let inputs: Vec<Dual<N>> = slots.iter().map(|&k| x[k]).collect();
    dual::eval(p, &params, &inputs).expect("the committed program evaluates")
}

impl<'a> RiderTurnSolver<'a> {
    /// The solver for `rider`.
    pub fn new(rider: &'a LeanRider) -> RiderTurnSolver<'a> {
        let p = programs();
        let get = |n: &str| rider.params().get(n).unwrap_or(f64::NAN);
        let mass = ["mc", "md", "me", "mf", "mg"].iter().map(|n| get(n)).sum::<f64>();
        let rows = (
            std::array::from_fn(|i| match turn_rows_scene::PARAMS.get(i) {
                Some(&"lam") => rider.upright_pitch(),
                Some(n) => get(n),
                None => 0.0,
            }),
            INPUTS.map(|name| {
                turn_rows_scene::INPUTS
                    .iter()
                    .position(|n| *n == name)
                    .map_or(usize::MAX, |i| turn_rows_scene::PARAMS.len() + i)
            }),
        );
        RiderTurnSolver {
            rider,
            contact: arguments(&p.contact, rider),
            dynamics: arguments(&p.dynamics, rider),
            rows,
            rr: get("rr"),
            scale: mass * get("g"),
        }
    }

    /// The dynamics' outputs ([`dynamics_scene::OUTPUTS`]) at the inputs `x` ([`INPUTS`]), the
    /// pitch `x[1]` first projected onto the contact constraint by one Newton step.
    fn outputs<const N: usize>(&self, x: [Dual<N>; 12]) -> ([Dual<N>; 19], Dual<N>) {
        let p = programs();
        let h = eval(&p.contact, &self.contact, &x);
        let mut x = x;
        x[1] = x[1] - h[0] / h[1];
        let o = eval(&p.dynamics, &self.dynamics, &x);
        (std::array::from_fn(|k| o[k]), x[1])
    }

    fn inputs<const N: usize>(
        &self,
        lean: f64,
        pitch: f64,
        steer: Dual<N>,
        torso: Dual<N>,
        wheel: f64,
    ) -> [Dual<N>; 12] {
        let c = Dual::constant;
        [
            c(lean),
            c(pitch),
            steer,
            torso,
            c(0.0),
            c(wheel),
            c(0.0),
            c(0.0),
            c(0.0),
            c(0.0),
            c(0.0),
            c(0.0),
        ]
    }

    /// [`Rows`] at `(lean, pitch, steer, torso)` with the rear wheel's rate `wheel`, every
    /// other speed and every torque zero, the pitch first projected onto the contact
    /// constraint by one Newton step, $q_5^* = q_5 - h/h_{q_5}$ (as [`outputs`](Self::outputs)
    /// does): generated values and derivatives, with
    /// $\mathrm{d}q_5^*/\mathrm{d}q_7 = -(h_{q_7}h_{q_5} - h\,h_{q_5q_7})/h_{q_5}^2$.
    fn rows(&self, lean: f64, pitch: f64, steer: f64, torso: f64, wheel: f64) -> Rows {
        let (h, dh, hd) = self.rider.contact_derivatives(lean, pitch, steer);
        let projected = pitch - h / dh;
        let dproj = -(hd[0][2] * dh - h * hd[1][2]) / (dh * dh);
        let (mut a, slots) = self.rows;
        let values = [lean, projected, steer, torso, 0.0, wheel, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        for (&slot, v) in slots.iter().zip(values) {
            if let Some(x) = a.get_mut(slot) {
                *x = v;
            }
        }
        let o = turn_rows_scene::eval_array(&a);
        // Columns q5, q7, q9.
        let j = turn_rows_scene::jacobian_array(&o);
        Rows {
            f: [o[0], o[1]],
            d: std::array::from_fn(|r| [j[r][1] + j[r][0] * dproj, j[r][2]]),
            pitch: projected,
        }
    }

    /// The torso's lean in equilibrium at `(lean, pitch, steer)` by Newton from `guess`, and the
    /// roll row there; `None` when Newton does not converge within ±π/2.
    fn torso(
        &self,
        lean: f64,
        pitch: f64,
        steer: f64,
        guess: f64,
        wheel: f64,
    ) -> Option<(f64, f64)> {
        let mut q9 = guess;
        for _ in 0..50 {
            let r = self.rows(lean, pitch, steer, q9, wheel);
            let step = r.f[1] / r.d[1][1];
            if !step.is_finite() {
                return None;
            }
            q9 -= step;
            if q9.abs() >= std::f64::consts::FRAC_PI_2 {
                return None;
            }
            if step.abs() <= 1e-14 * (1.0 + q9.abs()) {
                return Some((q9, r.f[0]));
            }
        }
        None
    }

    /// $F$, $dF/dq_7$ and the pitch and torso lean at `steer`, from the guesses `g`.
    fn newton(
        &self,
        lean: f64,
        wheel: f64,
        steer: f64,
        g: (f64, f64),
    ) -> Option<(f64, f64, (f64, f64))> {
        let pitch = self.rider.pitch_near(lean, g.0, steer)?;
        let (q9, _) = self.torso(lean, pitch, steer, g.1, wheel)?;
        let r = self.rows(lean, pitch, steer, q9, wheel);
        let df = r.d[0][0] - r.d[0][1] * r.d[1][0] / r.d[1][1];
        Some((r.f[0], df, (r.pitch, q9)))
    }

    /// Every steady turn at the rear contact's speed `speed` (m/s) and the roll `lean` (rad).
    ///
    /// # Errors
    /// [`TurnError::Parameter`] naming a speed that is not positive and finite or a roll not
    /// strictly inside ±π/2; [`TurnError::Solver`] when the stability of a turn found cannot be
    /// computed (its mass matrix singular to working precision, or the eigenvalues not
    /// converging).
    pub fn turns(&self, speed: f64, lean: f64) -> Result<RiderTurns, TurnError> {
        check(speed, lean)?;
        let wheel = -speed / self.rr;
        let value = |steer: f64, g: (f64, f64)| {
            let pitch = self.rider.pitch_near(lean, g.0, steer)?;
            let (q9, f) = self.torso(lean, pitch, steer, g.1, wheel)?;
            f.is_finite().then_some((f, (pitch, q9)))
        };
        let newton = |steer: f64, g: (f64, f64)| self.newton(lean, wheel, steer, g);
        let start = (self.rider.upright_pitch(), 0.0);
        let roots = steer_roots(&value, &newton, start, ROOT_TOLERANCE * self.scale);
        let turns = roots
            .into_iter()
            .map(|(steer, (pitch, torso))| self.turn_at(speed, lean, steer, pitch, torso))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(RiderTurns { speed, lean, turns })
    }

    fn turn_at(
        &self,
        speed: f64,
        lean: f64,
        steer: f64,
        pitch: f64,
        torso: f64,
    ) -> Result<RiderTurn, TurnError> {
        let wheel = -speed / self.rr;
        let c = Dual::<0>::constant;
        let (o, pitch) = self.outputs(self.inputs(lean, pitch, c(steer), c(torso), wheel));
        let o = o.map(|d| d.value);
        let pitch = pitch.value;
        let yaw_rate = o[14];
        let steer_torque = -o[12];
        if mass_matrix_is_singular(&o) {
            return Err(TurnError::Solver {
                reason: "the mass matrix is singular at the turn (a pivot below 1e-10 of its \
                         largest diagonal entry): the accelerations, hence the stability, are \
                         not defined",
                steer,
            });
        }
        let mut x = [0.0; 13];
        x[3] = lean;
        x[5] = steer;
        x[7] = torso;
        x[9] = wheel;
        x[PITCH] = pitch;
        let stability = self.stability(&x, steer_torque).ok_or(TurnError::Solver {
            reason: "the eigenvalues of the linearisation did not converge",
            steer,
        })?;
        Ok(RiderTurn {
            speed,
            lean,
            steer,
            torso_lean: torso,
            pitch,
            yaw_rate,
            radius: speed / yaw_rate,
            steer_torque,
            rear_wheel_rate: wheel,
            roll_residual: o[10],
            torso_residual: o[13],
            rear_row_residual: o[11],
            stability,
        })
    }

    /// The Jacobian of [`LeanRider::rate`] at `x` (thirteen components, the pitch last and on
    /// the constraint) under the constant torques `torques` $(T_4, T_6, T_7, T_9)$, with the
    /// pitch projected as the simulation projects it: the generated
    /// [`LeanRider::jacobian`], what the stability is computed from;
    /// [`state_jacobian_dual`](Self::state_jacobian_dual) is its reference.
    pub fn state_jacobian(&self, x: &[f64; 13], torques: [f64; 4]) -> [[f64; 13]; 13] {
        self.rider.jacobian(x, &torques, Joint::Free)
    }

    /// [`state_jacobian`](Self::state_jacobian) by forward-mode dual numbers through the IR
    /// interpreter ([`carvallo_ir::dual`]) and the solve in dual arithmetic: no generated
    /// derivative, no chain rule written by hand.
    pub fn state_jacobian_dual(&self, x: &[f64; 13], torques: [f64; 4]) -> [[f64; 13]; 13] {
        let y: [Dual<13>; 13] = std::array::from_fn(|k| Dual::variable(x[k], k));
        let c = Dual::constant;
        let inputs = [
            y[3],
            y[PITCH],
            y[5],
            y[7],
            y[8],
            y[9],
            y[10],
            y[11],
            c(torques[0]),
            c(torques[1]),
            c(torques[2]),
            c(torques[3]),
        ];
        let (o, _) = self.outputs(inputs);
        let y12: [Dual<13>; 12] = std::array::from_fn(|k| y[k]);
        let d = rider::assemble(&o, &y12);
        std::array::from_fn(|i| d[i].grad)
    }

    /// The $7\times7$ block of [`state_jacobian`](Self::state_jacobian) over [`REDUCED`].
    pub fn reduced_jacobian(&self, x: &[f64; 13], torques: [f64; 4]) -> SMatrix<f64, 7, 7> {
        let j = self.state_jacobian(x, torques);
        SMatrix::from_fn(|r, c| j[REDUCED[r]][REDUCED[c]])
    }

    fn stability(&self, x: &[f64; 13], steer_torque: f64) -> Option<Stability<6>> {
        let a = self.reduced_jacobian(x, [0.0, 0.0, steer_torque, 0.0]);
        let schur = nalgebra::Schur::try_new(a, 1e-15, 10_000)?;
        let mut ev: Vec<Complex<f64>> = schur.complex_eigenvalues().iter().copied().collect();
        let k = (0..ev.len()).min_by(|&i, &j| ev[i].norm().total_cmp(&ev[j].norm()))?;
        let family = ev.remove(k);
        ev.sort_by(|a, b| b.re.total_cmp(&a.re).then(b.im.total_cmp(&a.im)));
        let eigenvalues: [Complex<f64>; 6] = ev.try_into().ok()?;
        let stable = eigenvalues.iter().all(|e| e.re < 0.0);
        Some(Stability { eigenvalues, family, stable })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::rng::SplitMix64;
    use crate::whipple::lean_rider::LeanRiderParams;

    /// [`RiderTurnSolver::rows`] by the route it replaced: dual numbers in the steer and the
    /// torso's lean through the IR interpreter ([`RiderTurnSolver::outputs`], the pitch
    /// projected in dual arithmetic), no generated derivative.
    fn rows_dual(
        s: &RiderTurnSolver<'_>,
        lean: f64,
        pitch: f64,
        steer: f64,
        torso: f64,
        wheel: f64,
    ) -> Rows {
        let x =
            s.inputs(lean, pitch, Dual::<2>::variable(steer, 0), Dual::variable(torso, 1), wheel);
        let (o, pitch) = s.outputs(x);
        let (f4, f9) = (o[10], o[13]);
        Rows { f: [f4.value, f9.value], d: [f4.grad, f9.grad], pitch: pitch.value }
    }

    #[test]
    fn the_generated_turn_derivatives_equal_the_dual_numbers_they_replaced() {
        // At 40 seeded steady states of Browser + Jason (roll, steer, torso lean, speed; the
        // pitch on the contact constraint, then, for half of them, moved by 1e-9 rad so that
        // the projection's second-order term counts): the rows f_q4, f_q9 and their
        // derivatives in the steer (through the projected pitch) and the torso's lean, as the
        // torso's Newton steps and dF/dq7 use them, against the dual numbers they replaced:
        // 1e-12 of each row's largest entry. Dropping the pitch's part of d/dq7 (the
        // constraint moves the pitch as the steer turns) fails at the first state.
        let rider = LeanRider::new(LeanRiderParams::browser_jason()).expect("the rider");
        let s = RiderTurnSolver::new(&rider);
        let mut rng = SplitMix64(3507);
        let mut worst = 0.0f64;
        for k in 0..40 {
            let lean = rng.uniform(-0.6, 0.6);
            let steer = rng.uniform(-1.2, 1.2);
            let torso = rng.uniform(-0.4, 0.4);
            let wheel = -rng.uniform(0.5, 10.0) / s.rr;
            let on = rider.pitch_near(lean, rider.upright_pitch(), steer).expect("pitch");
            let pitch = if k % 2 == 0 { on } else { on + 1e-9 };
            let got = s.rows(lean, pitch, steer, torso, wheel);
            let want = rows_dual(&s, lean, pitch, steer, torso, wheel);
            assert!((got.pitch - want.pitch).abs() <= 1e-15, "state {k}: {got:?} vs {want:?}");
            for r in 0..2 {
                let row = [want.f[r], want.d[r][0], want.d[r][1]];
                let scale = row.iter().fold(1.0f64, |m, x| m.max(x.abs()));
                for (g, w) in [got.f[r], got.d[r][0], got.d[r][1]].into_iter().zip(row) {
                    let err = (g - w).abs() / scale;
                    worst = worst.max(err);
                    assert!(err <= 1e-12, "state {k}, row {r}: {got:?} vs dual numbers {want:?}");
                }
            }
        }
        eprintln!(
            "turn rows, generated vs dual numbers: worst {worst:.2e} of the row's largest; \
             turn_rows_scene {} operations ({} derivatives of {})",
            turn_rows_scene::OP_COUNT,
            turn_rows_scene::JACOBIAN_NONZEROS,
            2 * 3
        );
    }
}
