//! Yeadon's solids (Yeadon 1990-ii, Appendix B): the stadium (a rectangle of half-sides $t$ and
//! $r$ with a half-disc of radius $r$ on each short side), the stadium solid between two stadia,
//! and the semi-ellipsoid of the head; each with its mass, mass centre on its axis and inertia
//! about that mass centre in its own frame ($x$ along the stadium's thickness, $z$ along the
//! axis from the first stadium to the second).
//!
//! A stadium solid of height $h$ tapers linearly, $r = r_0(1 + a z/h)$, $t = t_0(1 + b z/h)$
//! with $a = (r_1 - r_0)/r_0$, $b = (t_1 - t_0)/t_0$; its properties are the integrals
//! $F_1 \ldots F_5$ of Yeadon's appendix, for instance the mass
//! $m = D h r_0 (4 t_0 F_1(a, b) + \pi r_0 F_1(a, a))$ with $F_1(a, b) = \int_0^1 (1 + a u)(1 + b u)\,du$.
//! A first stadium of zero thickness (a circle, $b$ undefined) is handled, as in yeadon, by
//! building the solid from the other end.
//!
//! [`Variant::Published`] reproduces yeadon 2.0.1's `solid.py` to rounding, two errors
//! included (found by this port's closed-form tests, see [`Variant`]);
//! [`Variant::Corrected`] computes the integrals as they are.

use crate::error::ParameterError;

use super::Variant;

const PI: f64 = std::f64::consts::PI;

/// A stadium: half-thickness `thickness` ($t$, half the straight side) and `radius` ($r$); a
/// circle when $t = 0$.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stadium {
    /// $r$, the radius of the rounded ends.
    pub radius: f64,
    /// $t$, half the length of the straight sides.
    pub thickness: f64,
    /// The width $2t + 2r$.
    pub width: f64,
    /// The perimeter $4t + 2\pi r$.
    pub perimeter: f64,
    /// Whether the long direction is anteroposterior (the heel) rather than mediolateral.
    pub anteroposterior: bool,
}

/// How a stadium was made from what was measured: `Some(text)` when a measured stadium was
/// impossible ($2 < p/w < \pi$ broken) and taken as a circle, as yeadon does (it warns).
pub type StadiumNote = Option<String>;

impl Stadium {
    fn from_radius_thickness(radius: f64, thickness: f64) -> Stadium {
        Stadium {
            radius,
            thickness,
            perimeter: 4.0 * thickness + 2.0 * PI * radius,
            width: 2.0 * thickness + 2.0 * radius,
            anteroposterior: false,
        }
    }

    /// A circle of radius `radius` (yeadon's `_set_as_circle`).
    pub fn circle(radius: f64) -> Stadium {
        let perimeter = 2.0 * PI * radius;
        Stadium { radius, thickness: 0.0, perimeter, width: perimeter / PI, anteroposterior: false }
    }

    /// A circle of perimeter `perimeter`.
    ///
    /// # Errors
    /// [`ParameterError`] naming `name` for a perimeter that is not positive and finite.
    pub fn from_perimeter(name: &'static str, perimeter: f64) -> Result<Stadium, ParameterError> {
        ParameterError::check_positive(name, perimeter)?;
        Ok(Stadium::circle(perimeter / (2.0 * PI)))
    }

    /// The stadium of perimeter `p` and width `w`: $t = (\pi w - p)/(2\pi - 4)$,
    /// $r = (p - 2w)/(2\pi - 4)$; when that gives a negative $t$ or $r$, the circle of perimeter
    /// `p` with a note.
    ///
    /// # Errors
    /// [`ParameterError`] naming `name` when $r = 0$ ($p = 2w$).
    pub fn from_perimeter_width(
        name: &'static str,
        p: f64,
        w: f64,
    ) -> Result<(Stadium, StadiumNote), ParameterError> {
        let thickness = (PI * w - p) / (2.0 * PI - 4.0);
        let radius = (p - 2.0 * w) / (2.0 * PI - 4.0);
        let s = Stadium { radius, thickness, width: w, perimeter: p, anteroposterior: false };
        Self::checked(name, s, || Stadium::circle(p / (2.0 * PI)), "a circle of that perimeter")
    }

    /// The stadium of depth `d` ($2r$) and width `w`: the perimeter $2w + (\pi - 2)d$, then as
    /// [`from_perimeter_width`](Self::from_perimeter_width); when impossible, the circle of
    /// diameter `w` with a note.
    ///
    /// # Errors
    /// As [`from_perimeter_width`](Self::from_perimeter_width).
    pub fn from_depth_width(
        name: &'static str,
        d: f64,
        w: f64,
    ) -> Result<(Stadium, StadiumNote), ParameterError> {
        let p = 2.0 * w + (PI - 2.0) * d;
        let thickness = (PI * w - p) / (2.0 * PI - 4.0);
        let radius = (p - 2.0 * w) / (2.0 * PI - 4.0);
        let s = Stadium { radius, thickness, width: w, perimeter: p, anteroposterior: false };
        Self::checked(name, s, || Stadium::circle(0.5 * w), "a circle of that width")
    }

    /// The stadium of half-thickness `thickness` and radius `radius`.
    ///
    /// # Errors
    /// [`ParameterError`] naming `name` when either is negative or the radius is zero.
    pub fn from_thickness_radius(
        name: &'static str,
        thickness: f64,
        radius: f64,
    ) -> Result<Stadium, ParameterError> {
        let s = Stadium::from_radius_thickness(radius, thickness);
        if radius == 0.0 || !radius.is_finite() {
            return Err(ParameterError::InvalidParameter {
                name,
                value: radius,
                reason: "the stadium's radius must be positive",
            });
        }
        if radius < 0.0 || thickness < 0.0 || !thickness.is_finite() {
            return Err(ParameterError::InvalidParameter {
                name,
                value: thickness.min(radius),
                reason: "the stadium's radius and thickness must not be negative",
            });
        }
        Ok(s)
    }

    fn checked(
        name: &'static str,
        s: Stadium,
        fallback: impl Fn() -> Stadium,
        what: &str,
    ) -> Result<(Stadium, StadiumNote), ParameterError> {
        if s.radius == 0.0 || !s.radius.is_finite() || !s.thickness.is_finite() {
            return Err(ParameterError::InvalidParameter {
                name,
                value: s.perimeter / s.width,
                reason:
                    "perimeter / width must lie between 2 and pi (the stadium's radius is zero)",
            });
        }
        if s.radius < 0.0 || s.thickness < 0.0 {
            let c = fallback();
            if !(c.radius > 0.0 && c.radius.is_finite()) {
                return Err(ParameterError::InvalidParameter {
                    name,
                    value: c.radius,
                    reason: "the stadium's radius must be positive",
                });
            }
            let note = format!(
                "stadium {name}: perimeter / width = {:?} is not between 2 and pi; taken as {what} \
                 (radius {:?} m), as yeadon does",
                s.perimeter / s.width,
                c.radius
            );
            return Ok((c, Some(note)));
        }
        Ok((s, None))
    }

    /// The same stadium with its long direction anteroposterior.
    pub fn anteroposterior(self) -> Stadium {
        Stadium { anteroposterior: true, ..self }
    }
}

/// A solid's mass, its mass centre on its axis (`z` from its first end) and its principal
/// moments about the mass centre (`[Ixx, Iyy, Izz]`, in its frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidBody {
    /// Mass (kg).
    pub mass: f64,
    /// Height (m), the distance between its two ends.
    pub height: f64,
    /// The mass centre's distance from the first end along the axis (m).
    pub z: f64,
    /// Moments of inertia about the mass centre, `[Ixx, Iyy, Izz]` (kg m²).
    pub inertia: [f64; 3],
}

fn f1(a: f64, b: f64) -> f64 {
    1.0 + (a + b) * 0.5 + a * b / 3.0
}

fn f2(a: f64, b: f64) -> f64 {
    0.5 + (a + b) / 3.0 + a * b * 0.25
}

fn f3(a: f64, b: f64) -> f64 {
    1.0 / 3.0 + (a + b) / 4.0 + a * b * 0.2
}

fn f4(a: f64, b: f64) -> f64 {
    1.0 + (a + 3.0 * b) * 0.5
        + (a * b + b.powi(2))
        + (3.0 * a * b.powi(2) + b.powi(3)) * 0.25
        + a * b.powi(3) * 0.2
}

fn f5(a: f64, b: f64) -> f64 {
    1.0 + (a + b)
        + (a.powi(2) + 4.0 * a * b + b.powi(2)) / 3.0
        + a * b * (a + b) * 0.5
        + a.powi(2) * b.powi(2) * 0.2
}

/// The stadium solid of density `density` and height `h` from `s0` (at its first end) to `s1`
/// (yeadon's `StadiumSolid.calc_rel_properties`).
///
/// With [`Variant::Published`], two errors of yeadon 2.0.1 are kept: when both stadia are
/// circles (a truncated cone) the mass centre is measured from the wrong end, and $I_x$ has
/// $\tfrac43 r_0 t_0^3 F_4(a, b)$ (the rectangle's $\int x^2$) where $\int y^2$ gives
/// $\tfrac43 r_0^3 t_0 F_4(b, a)$.
pub fn stadium_solid(
    density: f64,
    s0: &Stadium,
    s1: &Stadium,
    h: f64,
    variant: Variant,
) -> SolidBody {
    let d = density;
    let swapped = s0.thickness == 0.0;
    let (r0, t0, r1, t1) = if swapped {
        (s1.radius, s1.thickness, s0.radius, s0.thickness)
    } else {
        (s0.radius, s0.thickness, s1.radius, s1.thickness)
    };
    let a = (r1 - r0) / r0;
    let b = if t0 == 0.0 { 1.0 } else { (t1 - t0) / t0 };
    let mass = d * h * r0 * (4.0 * t0 * f1(a, b) + PI * r0 * f1(a, a));
    let zcom = d * h.powi(2) * (4.0 * r0 * t0 * f2(a, b) + PI * r0.powi(2) * f2(a, a)) / mass;
    let z = match variant {
        Variant::Published if swapped && t0 != 0.0 => h - zcom,
        Variant::Published => zcom,
        Variant::Corrected if swapped => h - zcom,
        Variant::Corrected => zcom,
    };
    let iz = d
        * h
        * (4.0 * r0 * t0.powi(3) * f4(a, b) / 3.0
            + PI * r0.powi(2) * t0.powi(2) * f5(a, b)
            + 4.0 * r0.powi(3) * t0 * f4(b, a)
            + PI * r0.powi(4) * f4(a, a) * 0.5);
    let axial = d * h.powi(3) * (4.0 * r0 * t0 * f3(a, b) + PI * r0.powi(2) * f3(a, a));
    let iy = d
        * h
        * (4.0 * r0 * t0.powi(3) * f4(a, b) / 3.0
            + PI * r0.powi(2) * t0.powi(2) * f5(a, b)
            + 8.0 * r0.powi(3) * t0 * f4(b, a) / 3.0
            + PI * r0.powi(4) * f4(a, a) * 0.25)
        + axial;
    let rectangle_y2 = match variant {
        Variant::Published => 4.0 * r0 * t0.powi(3) * f4(a, b) / 3.0,
        Variant::Corrected => 4.0 * r0.powi(3) * t0 * f4(b, a) / 3.0,
    };
    let ix = d * h * (rectangle_y2 + PI * r0.powi(4) * f4(a, a) * 0.25) + axial;
    let shift = mass * zcom.powi(2);
    let (mut ixc, mut iyc) = (ix - shift, iy - shift);
    if s0.anteroposterior || s1.anteroposterior {
        // yeadon rotates the inertia by pi/2 about z: x and y exchange.
        std::mem::swap(&mut ixc, &mut iyc);
    }
    SolidBody { mass, height: h, z, inertia: [ixc, iyc, iz] }
}

/// The semi-ellipsoid of density `density` on a circular base of perimeter `perimeter` and of
/// height `h` (the top of the head): $m = \tfrac23 \pi D r^2 h$, $z = \tfrac38 h$,
/// $I_z = \tfrac{4}{15}\pi D r^4 h$, $I_x = I_y = \pi D (\tfrac{2}{15} r^2 h (r^2 + h^2) - \tfrac{3}{32} r^2 h^3)$.
pub fn semi_ellipsoid(density: f64, perimeter: f64, h: f64) -> SolidBody {
    let (d, r) = (density, perimeter / (2.0 * PI));
    let mass = d * 2.0 / 3.0 * PI * r.powi(2) * h;
    let iz = d * 4.0 / 15.0 * PI * r.powi(4) * h;
    let ix = d
        * PI
        * (2.0 / 15.0 * r.powi(2) * h * (r.powi(2) + h.powi(2))
            - 3.0 / 32.0 * r.powi(2) * h.powi(3));
    SolidBody { mass, height: h, z: 3.0 / 8.0 * h, inertia: [ix, ix, iz] }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs().max(1e-300)
    }

    #[test]
    fn a_stadium_solid_of_two_equal_circles_is_a_cylinder() {
        let (d, r, h) = (1050.0, 0.06, 0.3);
        let c = Stadium::circle(r);
        for variant in [Variant::Published, Variant::Corrected] {
            let s = stadium_solid(d, &c, &c, h, variant);
            let m = d * PI * r * r * h;
            assert!(close(s.mass, m, 1e-14), "{s:?}");
            assert!(close(s.z, h / 2.0, 1e-14));
            let transverse = m * (r * r / 4.0 + h * h / 12.0);
            assert!(close(s.inertia[0], transverse, 1e-13), "{s:?} {transverse}");
            assert!(close(s.inertia[1], transverse, 1e-13));
            assert!(close(s.inertia[2], m * r * r / 2.0, 1e-14));
        }
    }

    #[test]
    fn a_truncated_cone_has_its_mass_centre_nearer_the_wide_end() {
        // Frustum of radii r0 (first end) and r1, height h: z = h (r0² + 2 r0 r1 + 3 r1²) /
        // (4 (r0² + r0 r1 + r1²)) from the first end; volume π h (r0² + r0 r1 + r1²) / 3.
        let (r0, r1, h, d) = (1.0, 2.0, 1.0, 1.0);
        let (c0, c1) = (Stadium::circle(r0), Stadium::circle(r1));
        let z =
            h * (r0 * r0 + 2.0 * r0 * r1 + 3.0 * r1 * r1) / (4.0 * (r0 * r0 + r0 * r1 + r1 * r1));
        let m = d * PI * h * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
        let right = stadium_solid(d, &c0, &c1, h, Variant::Corrected);
        assert!(close(right.mass, m, 1e-14));
        assert!(close(right.z, z, 1e-14), "{} {z}", right.z);
        // yeadon 2.0.1 measures it from the other end (17/28 against 11/28 here).
        let published = stadium_solid(d, &c0, &c1, h, Variant::Published);
        assert!(close(published.z, h - z, 1e-14), "{} {}", published.z, h - z);
        // Izz = 3 m (r1⁵ - r0⁵) / (10 (r1³ - r0³)) for a frustum.
        let izz = 3.0 * m * (r1.powi(5) - r0.powi(5)) / (10.0 * (r1.powi(3) - r0.powi(3)));
        assert!(close(right.inertia[2], izz, 1e-14));
    }

    #[test]
    fn a_stadium_prism_has_the_stadium_area_moments() {
        // Constant stadium of half-thickness t and radius r: area 4 r t + π r², and the area
        // moments ∫x² = 4/3 r t³ + π r² t² + 8/3 r³ t + π r⁴/4, ∫y² = 4/3 t r³ + π r⁴/4.
        let (t, r, h, d) = (0.1, 0.05, 0.2, 1000.0);
        let s = Stadium::from_thickness_radius("Ls0", t, r).expect("valid");
        let area = 4.0 * r * t + PI * r * r;
        let x2 = 4.0 / 3.0 * r * t.powi(3)
            + PI * r * r * t * t
            + 8.0 / 3.0 * r.powi(3) * t
            + PI * r.powi(4) / 4.0;
        let y2 = 4.0 / 3.0 * t * r.powi(3) + PI * r.powi(4) / 4.0;
        let m = d * area * h;
        let right = stadium_solid(d, &s, &s, h, Variant::Corrected);
        assert!(close(right.mass, m, 1e-14));
        assert!(close(right.z, h / 2.0, 1e-14));
        let axial = m * h * h / 12.0;
        assert!(close(right.inertia[0], d * h * y2 + axial, 1e-13), "{right:?}");
        assert!(close(right.inertia[1], d * h * x2 + axial, 1e-13));
        assert!(close(right.inertia[2], d * h * (x2 + y2), 1e-13));
        // yeadon 2.0.1's Ixx has r t³ for t r³: off by 4/3 D h r t (t² - r²).
        let published = stadium_solid(d, &s, &s, h, Variant::Published);
        let error = 4.0 / 3.0 * d * h * r * t * (t * t - r * r);
        assert!(close(published.inertia[0] - right.inertia[0], error, 1e-12));
        assert_eq!(published.inertia[1..], right.inertia[1..]);
        // A stadium whose width is its radius' double is a circle.
        let round = Stadium::from_thickness_radius("Ls0", 0.0, r).expect("valid");
        assert_eq!(round, Stadium::circle(r));
    }

    #[test]
    fn a_semi_ellipsoid_of_equal_axes_is_a_hemisphere() {
        let (r, d) = (0.1, 1000.0);
        let s = semi_ellipsoid(d, 2.0 * PI * r, r);
        let m = d * 2.0 / 3.0 * PI * r.powi(3);
        assert!(close(s.mass, m, 1e-14));
        assert!(close(s.z, 3.0 / 8.0 * r, 1e-14));
        assert!(close(s.inertia[2], 2.0 / 5.0 * m * r * r, 1e-14));
        assert!(close(s.inertia[0], 83.0 / 320.0 * m * r * r, 1e-14));
    }

    #[test]
    fn impossible_stadia_become_circles_with_a_note() {
        // p / w = 3.2 > pi: yeadon takes the circle of that perimeter.
        let (s, note) = Stadium::from_perimeter_width("Ls1", 0.32, 0.1).expect("fallback");
        assert_eq!(s, Stadium::circle(0.32 / (2.0 * PI)));
        assert!(note.expect("a note").contains("taken as a circle of that perimeter"));
        let (s, note) = Stadium::from_perimeter_width("Ls1", 0.3, 0.1).expect("valid");
        assert!(note.is_none());
        assert!(close(s.perimeter, 4.0 * s.thickness + 2.0 * PI * s.radius, 1e-15));
        let e = Stadium::from_perimeter_width("Ls1", 0.2, 0.1).unwrap_err();
        assert!(e.to_string().starts_with("invalid Ls1 2.0: perimeter / width"), "{e}");
    }
}
