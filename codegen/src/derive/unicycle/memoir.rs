//! The memoir's printed unicycle formulas (Part I, ch. II, n° 21–41, and n° 74, 78),
//! transcribed by hand from the OCR (see [`crate::memoir`]).
//!
//! Nothing here is derived. Conventions as in [`crate::derive::hoop::memoir`]: equations are written
//! "first member − second member"; `dp`, `dn`, `ds` stand for p', n', s'; `z` is the rider's
//! height of centre of gravity on Ok (called h from n° 39 on); `A`, `B`, `C`, `L`, `mu` are
//! the rider's constants of n° 21 and `A1`, `B1`, `C1`, `mu1` the wheel's. Where the memoir
//! merges a rider letter with the wheel's (n° 24: "désigner encore la somme A + A1 par la
//! lettre A"), the transcription keeps the printed letter. The OCR's "μ0", "μ1" of n° 36 for
//! the rider's mass, its "μhR" for "μgh" of n° 74 and its "\tilde s / R" for h/R of n° 32 are
//! kept as printed where a transcription is marked "as printed", read otherwise.

use crate::memoir::printed;
pub use crate::memoir::Printed;

printed! {
    // n° 23, (2): virtual works of the rider's inertia forces.
    RIDER_P, "23", "A*dp - L*dn*cos(theta) - mu*R*z*s*n*cos(theta) + (C - B)*n^2*sin(theta)*cos(theta)";
    RIDER_N, "23", "(C*cos(theta)^2 + B*sin(theta)^2)*dn + mu*R*z*ds*sin(theta) - L*dp*cos(theta) + 2*(B - C)*p*n*sin(theta)*cos(theta) + L*p^2*sin(theta)";
    RIDER_S, "23", "mu*R^2*ds + mu*R*z*(dn*sin(theta) + 2*p*n*cos(theta))";
    // n° 24, (3): the wheel's, from n° 6.
    WHEEL_P, "24", "A1*dp - B1*s*n*cos(theta) + (C1 - B1)*n^2*sin(theta)*cos(theta)";
    WHEEL_N, "24", "(C1*cos(theta)^2 + B1*sin(theta)^2)*dn + B1*ds*sin(theta) + 2*(B1 - C1)*p*n*sin(theta)*cos(theta) + (B1 - mu1*R^2)*p*s*cos(theta)";
    WHEEL_S, "24", "B1*ds + B1*dn*sin(theta) + (B1 + A1 - C1)*p*n*cos(theta)";
    // n° 24: the equations of motion with the merged letters (motor moment 0).
    EQ_P, "24", "A*dp - L*dn*cos(theta) - mu*R*z*s*n*cos(theta) + (C - B)*n^2*sin(theta)*cos(theta) - mu*z*g*sin(theta)";
    EQ_N, "24", "(C*cos(theta)^2 + B*sin(theta)^2)*dn + mu*R*z*ds*sin(theta) - L*dp*cos(theta) + 2*(B - C)*p*n*sin(theta)*cos(theta) + L*p^2*sin(theta) + (B1 - mu1*R^2)*p*s*cos(theta)";
    EQ_S, "24", "mu*R^2*ds + mu*R*z*dn*sin(theta) + 2*mu*R*z*p*n*cos(theta)";
    // n° 74: twice the rider's kinetic energy (L = 0), the corrections and (θ), (ν), (σ).
    TWICE_KINETIC_74, "74", "mu*R^2*s^2 + A*p^2 + (C*cos(theta)^2 + B*sin(theta)^2)*n^2 + 2*mu*R*z*s*n*sin(theta)";
    CORRECTION_NU_74, "74", "-mu*R*z*p*s*cos(theta)";
    CORRECTION_SIGMA_74, "74", "mu*R*z*p*n*cos(theta)";
    LAGRANGE_THETA_74_AS_PRINTED, "74", "A*dp - (B - C)*n^2*sin(theta)*cos(theta) - mu*R*z*s*n*cos(theta) - mu*z*R*sin(theta)";
    LAGRANGE_THETA_74, "74", "A*dp - (B - C)*n^2*sin(theta)*cos(theta) - mu*R*z*s*n*cos(theta) - mu*g*z*sin(theta)";
    LAGRANGE_NU_74, "74", "(C*cos(theta)^2 + B*sin(theta)^2)*dn + mu*R*z*ds*sin(theta) + 2*(B - C)*p*n*sin(theta)*cos(theta)";
    LAGRANGE_SIGMA_74, "74", "mu*R^2*ds + mu*R*z*dn*sin(theta) + 2*mu*R*z*p*n*cos(theta)";
    // n° 29: (E).
    EQUILIBRIUM, "29", "(B - C)*n^2*sin(theta)*cos(theta) + mu*R*z*s*n*cos(theta) + mu*g*z*sin(theta)";
    // n° 30: D complete and steady.
    SKID_FULL, "30", "-(R*n*s + z*n^2*sin(theta) + z*(p^2*sin(theta) - dp*cos(theta)))/(g + z*(p^2*cos(theta) + dp*sin(theta)))";
    SKID, "30", "-(R*n*s + z*n^2*sin(theta))/g";
    // n° 32: (E) and (D) with B - C = mu z^2 and s, n in units of sqrt(g/R).
    EQUILIBRIUM_N32, "32", "z/R*n^2*sin(theta) + s*n + tan(theta)";
    SKID_N32, "32", "-n*s - z/R*n^2*sin(theta)";
    // n° 34: system (I) (L = 0, merged letters).
    SYSTEM_I_DP, "34", "(mu*R*z*s*n*cos(theta) + (B - C)*n^2*sin(theta)*cos(theta) + mu*g*z*sin(theta))/A";
    SYSTEM_I_DN, "34", "(mu*R^2*(-2*(B - C)*p*n*sin(theta)*cos(theta) - (B1 - mu1*R^2)*p*s*cos(theta)) - mu*R*z*sin(theta)*(-2*mu*R*z*p*n*cos(theta)))/((C*cos(theta)^2 + B*sin(theta)^2)*mu*R^2 - mu^2*R^2*z^2*sin(theta)^2)";
    SYSTEM_I_DS, "34", "((C*cos(theta)^2 + B*sin(theta)^2)*(-2*mu*R*z*p*n*cos(theta)) - mu*R*z*sin(theta)*(-2*(B - C)*p*n*sin(theta)*cos(theta) - (B1 - mu1*R^2)*p*s*cos(theta)))/((C*cos(theta)^2 + B*sin(theta)^2)*mu*R^2 - mu^2*R^2*z^2*sin(theta)^2)";
    // n° 36: A times the stability first member at theta = 0, n = 0 (mu0, mu1 of the OCR read as mu).
    STRAIGHT_36, "36", "-mu*g*z + mu*R*z*(B1 - mu1*R^2)/C*s^2";
    // n° 39: A times the stability first member, E = B - C - mu h^2, infinitely light wheel.
    STABILITY_39, "39", "(C + (B - C - mu*z^2)*(1 + cos(theta)^2))/(C + (B - C - mu*z^2)*sin(theta)^2)*mu*R*z*s*n*sin(theta) + (C*mu*z^2 + (B - C - mu*z^2)*((mu*z^2 + (B - C - mu*z^2))*sin(theta)^2*(1 + 2*cos(theta)^2) - C*(cos(theta)^2 - sin(theta)^2)))/(C + (B - C - mu*z^2)*sin(theta)^2)*n^2 - mu*g*z*cos(theta)";
    STABILITY_39_E0, "39", "mu*R*z*s*n*sin(theta) + mu*z^2*n^2 - mu*g*z*cos(theta)";
    STABILITY_39_N, "39", "s*n*sin(theta) + z/R*n^2 - cos(theta)";
    // n° 40: the intermediate case.
    STABILITY_40, "40", "mu*z^2*n^2 + (mu*R*z*sin(theta) + mu*z^2*sin(theta)*cos(theta)^2)*s*n + mu*R*z*s^2*cos(theta)^2 - mu*g*z*cos(theta)";
    STABILITY_40_N, "40", "z/R*n^2 + (1 + z/R*cos(theta)^2)*s*n*sin(theta) + s^2*cos(theta)^2 - cos(theta)";
    // n° 41: the trinomial S(n^2).
    TRINOMIAL_41, "41", "z/R*cos(theta)^2*n^4 - (1/cos(theta) - z/R*sin(theta)^2*cos(theta))*n^2 + sin(theta)^2";
    // n° 78, (2) and (3) at theta = 0, n = 0 (merged letters, B1 = 2 mu1 R^2).
    PRODUCT_78, "78", "-C*mu*g*z + mu*mu1*R^3*z*s^2";
    SUM_78, "78", "L*R*s*(mu1*R - mu*z)";
}
