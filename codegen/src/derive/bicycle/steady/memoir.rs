//! The memoir's printed formulas of the bicycle's steady states and of the stability with
//! hands (Part II, ch. IV, n° 79–106), transcribed by hand from the OCR (see
//! [`crate::memoir`]).
//!
//! Nothing here is derived. Conventions: `deta`, `dnu` stand for the memoir's
//! $d\eta/d\theta$, $d\nu/d\theta$ (the OCR prints them "dr₁/dθ", "dy/dθ"), `deta_g`, `dnu_g`
//! for $d\eta/d\gamma$, $d\nu/d\gamma$; `deta_t` for the rate η′ (OCR "r′", "τ′"); `s1` the
//! front wheel's rolling rate on the ground, `theta1` its lean; the memoir's
//! $\beta = -\theta_1$ (n° 38) is written with `theta1` ($\sin\beta = -\sin\theta_1$,
//! $\tan\beta = -\tan\theta_1$). The front wheel's mass is `mu1` as in the memoir (which
//! gives both wheels the same constants $\mu_1, A_1, B_1, C_1$). Equations are written
//! "first member − second member"; tables are transcribed row by row, each row with the sign
//! printed in front of it ("Terme + Σ m M′|(dM/dθ)′", "Terme + Σ m g dz/dθ").

use crate::memoir::printed;
pub use crate::memoir::Printed;

printed! {
    // n° 85, table, first part: the steady "centrifugal" terms Σ m M'|(dM/dθ)'.
    FALL_REAR, "85", "B1*s*n*cos(theta) + (B1 - C1)*n^2*sin(theta)*cos(theta)";
    FALL_FRONT, "85", "(B1*s1*n*cos(theta1) + (B1 - C1)*n^2*sin(theta1)*cos(theta1))*(cos(alpha) - sin(alpha)*cos(theta)*deta)";
    FALL_FRAME, "85", "mu*R*h*s*n*cos(theta) + (B - C)*n^2*sin(theta)*cos(theta) + deta*(mu*R*e*(s*n*sin(theta) + n^2*sin(theta)^2 - n^2*sin(theta)*cos(theta)) + L*n^2*cos(theta)^2) - dnu*mu*R*e*s*n";
    // n° 85, table, second part: the gravity terms + Σ m g dz/dθ (n° 84).
    GRAV_REAR, "85", "-mu1*g*R*sin(theta)";
    GRAV_FRONT, "85", "-mu1*g*R*sin(theta1)*(cos(alpha) - sin(alpha)*cos(theta)*deta)";
    GRAV_FRAME, "85", "g*(-mu*h*sin(theta) + mu*e*cos(theta)*deta)";
    // n° 83, the six terms of Σ m M'|(dM/dθ)' for the loaded frame, non-steady (p, η' = deta_t,
    // (dη/dθ)' = ddeta, (dν/dθ)' = ddnu kept; the memoir underlines what vanishes in a steady
    // state). Term (4) is transcribed as printed: "μ R sin θ", where the steady row of n° 85
    // has μ R e.
    FRAME_83_1, "83", "mu*R*deta*(e*n*sin(theta) - e*deta_t)*(s + n*sin(theta))";
    FRAME_83_2, "83", "mu*R*s*dnu*(-e*n + h*p*cos(theta) + e*deta_t*sin(theta))";
    FRAME_83_3, "83", "mu*R*h*(s + deta_t)*n*cos(theta) + B*n*cos(theta)*(n*sin(theta) - deta_t) - n*sin(theta)*(L*p + C*n*cos(theta))";
    FRAME_83_4, "83", "deta*(-L*p^2 + (A - C - mu*R*h)*n*p*cos(theta) + n^2*cos(theta)*(L*cos(theta) - mu*R*sin(theta)))";
    FRAME_83_5, "83", "-ddeta*((B - mu*R*h)*n*sin(theta) + mu*R*(h - R)*s + mu*R*(2*h - R)*deta_t)";
    FRAME_83_6, "83", "ddnu*((mu*R*h*(s + deta_t) + B*(n*sin(theta) - deta_t))*sin(theta) + (L*p + C*n*cos(theta))*cos(theta))";
    // n° 86, (1): the reduced fall equation; (3)' of n° 86 bis; n° 87; n° 88 (1); n° 89.
    FALL_86, "86", "mu*R*h*s*n*cos(theta) + mu*g*h*sin(theta) - mu*g*e*cos(theta)*deta";
    TAN_THETA_86, "86", "-R/l*R*s^2/g*tan(alpha)";
    CURVATURE_87, "87", "-g/(R*s^2)*tan(theta)";
    RATIO_88, "88", "-g*l/(R^2*s^2)";
    EPSILON_BOUND_89, "89", "e/h*c/l";
    // n° 94, the two tables of the handlebar equation.
    STEER_FRONT, "94", "-sin(alpha)*cos(theta)*deta_g*(B1*s1*n*cos(theta1) + (B1 - C1)*n^2*sin(theta1)*cos(theta1)) + (-n*sin(eta)*cos(alpha) - n*sin(theta)*cos(eta)*sin(alpha))*(B1*s1*cos(theta1) + (B1 - C1)*n*sin(theta1)*cos(theta1))";
    STEER_FRAME, "94", "deta_g*(mu*R*e*(s*n*sin(theta) + n^2*sin(theta)^2 - n^2*sin(theta)*cos(theta)) + L*n^2*cos(theta)^2) - dnu_g*mu*R*e*s*n";
    STEER_GRAV_FRONT, "94", "mu1*R*g*sin(theta1)*sin(alpha)*cos(theta)*deta_g + mu1*R*g*sin(omega)*sin(theta1)";
    STEER_GRAV_FRAME, "94", "mu*e*g*cos(theta)*deta_g";
    // n° 95: the handlebar equation after the substitutions of s1, dη/dγ, dν/dγ (before (1)),
    // its form (1) and the ratio θ1/θ of (1)'.
    STEER_95_BEFORE, "95", "s*n*(B1*cos(theta1)*sin(eta) + mu*R*e*(R*sin(omega) - c)/(l*cos(alpha))*cos(theta1)) + mu1*R*g*sin(omega)*sin(theta1) + mu*e*g*(R*sin(omega) - c)/l*sin(theta1)";
    STEER_95, "95", "-(mu1*sin(omega) + mu*e/R*(R*sin(omega) - c)/l)*tan(theta1) - (2*mu1*sin(eta) + mu*e/R*(R*sin(omega) - c)/l)*R/l*R*s^2/g*tan(alpha)";
    THETA1_RATIO_95, "95", "(2*mu1*sin(eta) + mu*e/R*(R*sin(omega) - c)/l)/(mu1 + mu*e/R*(R*sin(omega) - c)/l)";
    // n° 99: twice the kinetic energy of the loaded frame; n° 100, (1)-(3); n° 102.
    KINETIC_FRAME, "99", "mu*R^2*(s + deta_t)^2 + 2*mu*R*h*(s + deta_t)*(n*sin(theta) - deta_t) + A*p^2 + B*(n*sin(theta) - deta_t)^2 + C*n^2*cos(theta)^2 - 2*L*p*n*cos(theta)";
    DT0_DP, "100", "A*p - L*n*cos(theta)";
    DT0_DETA, "100", "mu*R^2*(s + deta_t) + mu*R*h*(-s - 2*deta_t + n*sin(theta)) - B*(n*sin(theta) - deta_t)";
    DT0_DN, "100", "mu*R*h*(s + deta_t)*sin(theta) + B*sin(theta)*(n*sin(theta) - deta_t) + C*n*cos(theta)^2 - L*p*cos(theta)";
    DFDPP_102, "102", "A";
}
