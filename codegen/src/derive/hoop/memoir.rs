//! The memoir's printed hoop formulas, transcribed by hand from the 1897 text (see
//! [`crate::memoir`]) and parsed by symbolica.
//!
//! Nothing here is derived: these strings are what the derivations are checked against. Each
//! entry gives its section number as printed in the table of contents; equations are written
//! "first member − second member" (to be read "= 0"). `tan(theta)` stands for the memoir's
//! "tang θ"; `dp`, `dq`, `dr`, `dn`, `ds` stand for p', q', r', n', s'; `A`, `B`, `C` are the
//! moments of inertia left symbolic where the memoir leaves them so.

use crate::memoir::printed;
pub use crate::memoir::Printed;

printed! {
    // n° 4, (7): moments of inertia.
    INERTIA_A, "4", "3/2*mu*R^2";
    INERTIA_B, "4", "2*mu*R^2";
    INERTIA_C, "4", "1/2*mu*R^2";
    // n° 5: moment of the weight about O, component on I (the others are 0).
    WEIGHT_MOMENT_I, "5", "mu*g*R*sin(theta)";
    // n° 6: J = J1 + J2 on I, j, k (A, B, C symbolic).
    INERTIA_MOMENT_I, "6", "A*dp - B*q*r + C*r^2*tan(theta)";
    INERTIA_MOMENT_J, "6", "B*dq + (A - C)*p*r";
    INERTIA_MOMENT_K, "6", "C*dr + (mu*R^2 - A)*p*r*tan(theta) + (B - mu*R^2)*p*q";
    // n° 7, system (1) with the values (7).
    SYSTEM1_I, "7", "3/2*dp - 2*q*r + 1/2*r^2*tan(theta) - g/R*sin(theta)";
    SYSTEM1_J, "7", "2*dq + r*p";
    SYSTEM1_K, "7", "1/2*dr - 1/2*r*p*tan(theta) + p*q";
    // n° 7, system (2).
    SYSTEM2_P, "7", "3/2*dp - 2*s*n*cos(theta) - 3/2*n^2*sin(theta)*cos(theta) - g/R*sin(theta)";
    SYSTEM2_N, "7", "1/2*dn + p*s/cos(theta)";
    SYSTEM2_S, "7", "2*ds - 4*p*s*tan(theta) + 3*p*n*cos(theta)";
    // n° 8, system (1) solved.
    PQR_DP, "8", "2*g*sin(theta)/(3*R) + 4*q*r/3 - r^2*tan(theta)/3";
    PQR_DQ, "8", "-p*r/2";
    PQR_DR, "8", "p*r*tan(theta) - 2*p*q";
    // n° 8, (E).
    EQUILIBRIUM, "8", "2*g*sin(theta)/(3*R) + 4*s*n/3*cos(theta) + n^2*sin(theta)*cos(theta)";
    // n° 9: -f1 before the substitutions, and (S).
    MINUS_F1, "9", "-2*g*cos(theta)/(3*R) - 4*(dq*r + q*dr)/(3*p) + 2*r*dr/(3*p)*tan(theta) + r^2/(3*cos(theta)^2)";
    STABILITY, "9", "-2*g*cos(theta)/(3*R) + n^2 + 8*s*n*sin(theta)/3 + 8*s^2/3";
    // n° 10: centrifugal force of the centre (component on J) and D.
    CENTRE_FORCE_J, "10", "-mu*R*n^2*(sin(theta) + s/n)";
    SKID, "10", "-R/g*(n^2*sin(theta) + s*n)";
    // n° 11: moments about OI and their sum over mu R^2.
    MOMENT_CONVERSION, "11", "mu*R^2*s*n*cos(theta) + 3/2*mu*R^2*n^2*sin(theta)*cos(theta)";
    MOMENT_COMPOUND, "11", "mu*R^2*s*n*cos(theta)";
    MOMENT_WEIGHT, "11", "mu*g*R*sin(theta)";
    EQUILIBRIUM_DIRECT, "11", "g*sin(theta)/R + 2*s*n*cos(theta) + 3/2*n^2*sin(theta)*cos(theta)";
    // n° 12, normalised forms (g/R = 1).
    EQUILIBRIUM_N12, "12", "n^2 + 4*s/(3*sin(theta))*n + 2/(3*cos(theta))";
    STABILITY_N12, "12", "n^2 + 8*s*sin(theta)/3*n + 8*s^2/3 - 2*cos(theta)/3";
    SKID_N12, "12", "-n^2*sin(theta) - s*n";
    // n° 71: twice the kinetic energy.
    TWICE_KINETIC, "71", "A*p^2 + B*(s + n*sin(theta))^2 + C*n^2*cos(theta)^2";
    // n° 73 (printed "75"): correction terms and the modified equations (θ), (ν), (σ).
    CORRECTION_NU, "73", "-mu*R^2*p*s*cos(theta)";
    CORRECTION_SIGMA, "73", "(A - C)*p*n*cos(theta)";
    LAGRANGE_THETA, "73", "A*dp - B*s*n*cos(theta) - (B - C)*n^2*sin(theta)*cos(theta) - mu*g*R*sin(theta)";
    LAGRANGE_NU, "73", "B*ds*sin(theta) + (C*cos(theta)^2 + B*sin(theta)^2)*dn + (B - mu*R^2)*p*s*cos(theta) + 2*(B - C)*p*n*sin(theta)*cos(theta)";
    LAGRANGE_SIGMA, "73", "B*ds + B*dn*sin(theta) + (B + A - C)*p*n*cos(theta)";
}
