//! Time responses of the linearised bicycle as a plant ($\dot x = Ax + Bu$, [`super::plant`]):
//! to a unit step and a unit impulse of the roll or steer torque, and from an initial state,
//! through the matrix exponential.
//!
//! With $b$ the input's column of $B$,
//!
//! $$x_{\text{initial}}(t) = e^{At}x_0,\qquad x_{\text{impulse}}(t) = e^{At}\,b,\qquad
//! x_{\text{step}}(t) = \int_0^t e^{A\tau}\,d\tau\;b,$$
//!
//! all read off one exponential of the augmented matrix (Van Loan 1978):
//! $\exp\!\begin{pmatrix} A & b \\ 0 & 0 \end{pmatrix}t =
//! \begin{pmatrix} e^{At} & \int_0^t e^{A\tau}d\tau\,b \\ 0 & 1 \end{pmatrix}$, computed at each
//! time by nalgebra's scaling-and-squaring Padé approximation. Not the modal form: $A$ is
//! defective where two eigenvalues coalesce (the weave's birth from two real roots, 0.684 m/s for
//! the benchmark), where $V\,e^{\Lambda t}V^{-1}$ loses every digit; the exponential does not
//! care. Each time is computed on its own, so no error accumulates along the grid. The impulse
//! response is SciPy's `signal.impulse` ($x(0^+) = b$, as its `X0 + B`); the step response is
//! `signal.step`'s; the initial-condition response is `signal.lsim`'s with a zero input.

use nalgebra::{Matrix5, Vector4};

use super::model::Whipple;
use super::transfer::Input;
use crate::error::ParameterError;

/// What drives the response.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Excitation {
    /// A unit step (1 N m from $t = 0$) of the input, from rest.
    Step(Input),
    /// A unit impulse (1 N m s at $t = 0$) of the input, from rest.
    Impulse(Input),
    /// No input, from the state $(\varphi, \delta, \dot\varphi, \dot\delta)$.
    Initial([f64; 4]),
}

impl Whipple {
    /// The state $(\varphi, \delta, \dot\varphi, \dot\delta)$ at each of `times` (s) at speed `v`
    /// (see the [module docs](self)).
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming a time that is negative or not finite, a
    /// speed or an initial state that is not finite.
    pub fn time_response(
        &self,
        v: f64,
        excitation: Excitation,
        times: &[f64],
    ) -> Result<Vec<[f64; 4]>, ParameterError> {
        let bad =
            |name, value, reason| Err(ParameterError::InvalidParameter { name, value, reason });
        if !v.is_finite() {
            return bad("speed", v, "must be finite");
        }
        if let Some(&t) = times.iter().find(|t| !(t.is_finite() && **t >= 0.0)) {
            return bad("time", t, "must be finite and not negative");
        }
        let ss = self.state_space(v);
        let (column, x0) = match excitation {
            Excitation::Step(i) => (Some(ss.b.column(i.index()).into_owned()), None),
            Excitation::Impulse(i) => (None, Some(ss.b.column(i.index()).into_owned())),
            Excitation::Initial(x) => {
                if let Some(&x) = x.iter().find(|x| !x.is_finite()) {
                    return bad("initial state", x, "must be finite");
                }
                (None, Some(Vector4::from(x)))
            }
        };
        let mut m = Matrix5::<f64>::zeros();
        m.fixed_view_mut::<4, 4>(0, 0).copy_from(&ss.a);
        if let Some(b) = &column {
            m.fixed_view_mut::<4, 1>(0, 4).copy_from(b);
        }
        Ok(times
            .iter()
            .map(|&t| {
                let e = (m * t).exp();
                let x: Vector4<f64> = match (&column, &x0) {
                    (Some(_), _) => e.fixed_view::<4, 1>(0, 4).into_owned(),
                    (None, Some(x0)) => e.fixed_view::<4, 4>(0, 0) * x0,
                    (None, None) => Vector4::zeros(),
                };
                [x[0], x[1], x[2], x[3]]
            })
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::ode::rk4_step;
    use crate::whipple::WhippleParams;

    /// RK4 at a small step on $\dot x = Ax + bu$: the independent route.
    fn by_rk4(w: &Whipple, v: f64, excitation: Excitation, t_end: f64) -> [f64; 4] {
        let ss = w.state_space(v);
        let (u, mut x) = match excitation {
            Excitation::Step(i) => (ss.b.column(i.index()).into_owned(), Vector4::zeros()),
            Excitation::Impulse(i) => (Vector4::zeros(), ss.b.column(i.index()).into_owned()),
            Excitation::Initial(x0) => (Vector4::zeros(), Vector4::from(x0)),
        };
        let n = 20_000;
        let h = t_end / n as f64;
        let f = |x: [f64; 4]| -> [f64; 4] {
            let d = ss.a * Vector4::from(x) + u;
            [d[0], d[1], d[2], d[3]]
        };
        let mut s = [x[0], x[1], x[2], x[3]];
        for _ in 0..n {
            s = rk4_step(f, s, h);
        }
        x = Vector4::from(s);
        [x[0], x[1], x[2], x[3]]
    }

    #[test]
    fn equals_rk4_at_stable_unstable_and_defective_speeds() {
        let w = Whipple::new(WhippleParams::benchmark());
        // 0.684 m/s: the weave's birth, A (nearly) defective; 2: unstable weave; 5: stable.
        for v in [0.6840, 2.0, 5.0, 8.0] {
            for e in [
                Excitation::Step(Input::Steer),
                Excitation::Step(Input::Roll),
                Excitation::Impulse(Input::Steer),
                Excitation::Initial([0.01, -0.02, 0.1, 0.3]),
            ] {
                let got = w.time_response(v, e, &[0.0, 1.5]).expect("valid");
                let want = by_rk4(&w, v, e, 1.5);
                let scale = want.iter().fold(1e-3_f64, |m, x| m.max(x.abs()));
                for k in 0..4 {
                    assert!(
                        (got[1][k] - want[k]).abs() <= 1e-9 * scale,
                        "v {v} {e:?}: {got:?} {want:?}"
                    );
                }
                match e {
                    Excitation::Step(_) => assert_eq!(got[0], [0.0; 4]),
                    Excitation::Initial(x0) => assert_eq!(got[0], x0),
                    Excitation::Impulse(i) => {
                        let b = w.state_space(v).b;
                        assert_eq!(
                            got[0],
                            [
                                b[(0, i.index())],
                                b[(1, i.index())],
                                b[(2, i.index())],
                                b[(3, i.index())]
                            ]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn bad_times_and_states_are_named() {
        let w = Whipple::new(WhippleParams::benchmark());
        let e = w.time_response(5.0, Excitation::Step(Input::Steer), &[0.0, -1.0]).unwrap_err();
        assert_eq!(e.to_string(), "invalid time -1.0: must be finite and not negative");
        let e = w.time_response(5.0, Excitation::Initial([0.0, f64::NAN, 0.0, 0.0]), &[1.0]);
        assert_eq!(e.unwrap_err().to_string(), "invalid initial state NaN: must be finite");
        let e = w.time_response(f64::INFINITY, Excitation::Step(Input::Roll), &[1.0]);
        assert_eq!(e.unwrap_err().to_string(), "invalid speed inf: must be finite");
    }
}
