//! Yeadon's human body (yeadon 2.0.1's `Human`): the solids made from the measurements, grouped
//! into 11 segments joined at the hips, shoulders, knees, elbows and the spine, and the mass,
//! mass centre and inertia of the whole body for a configuration of its 21 joint angles.
//!
//! Frames and points are yeadon's: the origin at the centre of the lowest torso stadium `Ls0`
//! (the hip joint centres' level), $z$ up the torso, $x$ to the body's left, $y$ forward (in the
//! zero configuration, standing, arms down). Each segment's frame is its parent's turned by
//! body-fixed $x$–$y$–$z$ (Euler 1-2-3) rotations, $R = R_x(\alpha) R_y(\beta) R_z(\gamma)$
//! (yeadon's `euler_123`): the pelvis by (`somersault`, `tilt`, `twist`) from the body frame,
//! the thorax by (`PTsagittalFlexion`, `PTbending`, 0), the chest-head by
//! (`TCsagittalSpinalFlexion`, 0, `TCspinalTorsion`), the upper arms by (`CA1extension`,
//! `CA1adduction`, `CA1rotation`) and (`CB1extension`, `CB1abduction`, `CB1rotation`) at the
//! shoulders ($\pm$ half the width of `Ls4`, at the top of the nipple–shoulder solid), the
//! forearms by (`A1A2extension`, 0, 0), the thighs by (`PJ1extension`, `PJ1adduction`, 0) and
//! (`PK1extension`, `PK1abduction`, 0) at the hips ($\pm (t + r)/2$ of `Ls0`), the shanks by
//! (`J1J2flexion`, 0, 0). The torso's solids are stacked up its $z$ axis, the limbs' down.
//!
//! The left and right limbs' measurements are averaged (yeadon's default `symmetric=True`,
//! which BicycleParameters uses) and the densities are Dempster's (yeadon's default), all
//! scaled by one factor so that the body's mass is the measured `totalmass`.

use nalgebra::{Matrix3, Vector3};

use super::solid::{semi_ellipsoid, stadium_solid, SolidBody, Stadium};
use super::{Configuration, Measurements, Variant, YeadonError, MEASUREMENT_NAMES};

/// Dempster's segmental densities (kg/m³) as yeadon lists them: head-neck, shoulders, thorax,
/// abdomen-pelvis, upper arm, forearm, hand, thigh, lower leg, foot.
const DEMPSTER: Densities = Densities {
    head_neck: 1110.0,
    shoulders: 1040.0,
    thorax: 920.0,
    abdomen_pelvis: 1010.0,
    upper_arm: 1070.0,
    forearm: 1130.0,
    hand: 1160.0,
    thigh: 1050.0,
    lower_leg: 1090.0,
    foot: 1100.0,
};

#[derive(Clone, Copy, Debug)]
struct Densities {
    head_neck: f64,
    shoulders: f64,
    thorax: f64,
    abdomen_pelvis: f64,
    upper_arm: f64,
    forearm: f64,
    hand: f64,
    thigh: f64,
    lower_leg: f64,
    foot: f64,
}

impl Densities {
    fn scaled(&self, k: f64) -> Densities {
        Densities {
            head_neck: self.head_neck * k,
            shoulders: self.shoulders * k,
            thorax: self.thorax * k,
            abdomen_pelvis: self.abdomen_pelvis * k,
            upper_arm: self.upper_arm * k,
            forearm: self.forearm * k,
            hand: self.hand * k,
            thigh: self.thigh * k,
            lower_leg: self.lower_leg * k,
            foot: self.foot * k,
        }
    }
}

/// The mass, mass centre and inertia of a body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    /// Mass (kg).
    pub mass: f64,
    /// Mass centre (m) in the body frame from the origin.
    pub centre: [f64; 3],
    /// Inertia tensor about the mass centre in the body frame (kg m²).
    pub inertia: [[f64; 3]; 3],
}

/// The solids of the body, built once from the measurements (they do not depend on the
/// configuration).
#[derive(Clone, Debug)]
struct Solids {
    torso: [SolidBody; 8],
    left_arm: [SolidBody; 7],
    right_arm: [SolidBody; 7],
    left_leg: [SolidBody; 9],
    right_leg: [SolidBody; 9],
    /// The width of `Ls4` (the shoulders' distance is half of it each side).
    shoulder_width: f64,
    /// $t + r$ of `Ls0` (each hip at half of it).
    hip_width: f64,
}

/// Yeadon's human body from its measurements: [`mass_properties`](Self::mass_properties) for
/// any configuration.
#[derive(Clone, Debug)]
pub struct Human {
    solids: Solids,
    variant: Variant,
    notes: Vec<String>,
    density_scale: f64,
}

/// The stadium of `r`, its note (if any) kept in `notes`.
fn stadium_notes(
    r: Result<(Stadium, Option<String>), crate::error::ParameterError>,
    notes: &mut Vec<String>,
) -> Result<Stadium, YeadonError> {
    let (s, note) = r?;
    notes.extend(note);
    Ok(s)
}

/// A measurement by name (the names are those of [`MEASUREMENT_NAMES`]).
fn m(meas: &Measurements, name: &'static str) -> f64 {
    meas.get(name)
}

fn build(
    meas: &Measurements,
    d: &Densities,
    variant: Variant,
    notes: &mut Vec<String>,
) -> Result<Solids, YeadonError> {
    let pw = |name: &'static str, p: &'static str, w: &'static str, notes: &mut Vec<String>| {
        stadium_notes(Stadium::from_perimeter_width(name, m(meas, p), m(meas, w)), notes)
    };
    let circle = |name: &'static str| Stadium::from_perimeter(name, m(meas, name));
    // Torso.
    let ls0 = pw("Ls0", "Ls0p", "Ls0w", notes)?;
    let ls1 = pw("Ls1", "Ls1p", "Ls1w", notes)?;
    let ls2 = pw("Ls2", "Ls2p", "Ls2w", notes)?;
    let ls3 = pw("Ls3", "Ls3p", "Ls3w", notes)?;
    let ls4 =
        stadium_notes(Stadium::from_depth_width("Ls4", m(meas, "Ls4d"), m(meas, "Ls4w")), notes)?;
    // Yeadon's ISEG: the acromion stadium from the shoulder's.
    let radius5 = 0.57 * ls4.radius;
    let ls5 = Stadium::from_thickness_radius("Ls5", ls4.width / 2.0 - radius5, radius5)?;
    let neck = circle("Ls5p")?;
    let ls6 = circle("Ls6p")?;
    let ls7 = circle("Ls7p")?;
    let h = |a: &'static str, b: Option<&'static str>| match b {
        Some(b) => m(meas, a) - m(meas, b),
        None => m(meas, a),
    };
    let torso = [
        stadium_solid(d.abdomen_pelvis, &ls0, &ls1, h("Ls1L", None), variant),
        stadium_solid(d.abdomen_pelvis, &ls1, &ls2, h("Ls2L", Some("Ls1L")), variant),
        stadium_solid(d.thorax, &ls2, &ls3, h("Ls3L", Some("Ls2L")), variant),
        stadium_solid(d.thorax, &ls3, &ls4, h("Ls4L", Some("Ls3L")), variant),
        stadium_solid(d.shoulders, &ls4, &ls5, h("Ls5L", Some("Ls4L")), variant),
        stadium_solid(d.head_neck, &neck, &ls6, h("Ls6L", None), variant),
        stadium_solid(d.head_neck, &ls6, &ls7, h("Ls7L", Some("Ls6L")), variant),
        semi_ellipsoid(d.head_neck, m(meas, "Ls7p"), h("Ls8L", Some("Ls7L"))),
    ];
    for (k, s) in torso.iter().enumerate() {
        if s.height.is_nan() || s.height <= 0.0 {
            return Err(YeadonError::Parameter(crate::error::ParameterError::InvalidParameter {
                name: ["Ls1L", "Ls2L", "Ls3L", "Ls4L", "Ls5L", "Ls6L", "Ls7L", "Ls8L"][k],
                value: s.height,
                reason: "the torso's levels must rise (each length beyond the one before)",
            }));
        }
    }
    // Arms: stadia 0-3 circles, 4-7 perimeter and width; solid i from stadium i + 1 (its first
    // end, distal) to stadium i, built down the arm.
    let arm = |side: char, notes: &mut Vec<String>| -> Result<[SolidBody; 7], YeadonError> {
        let name = |s: &str| -> &'static str {
            let full = format!("L{side}{s}");
            MEASUREMENT_NAMES.iter().find(|n| **n == full).copied().unwrap_or("?")
        };
        let mut st = Vec::with_capacity(8);
        for k in 0..4 {
            st.push(Stadium::from_perimeter(
                name(&format!("{k}p")),
                m(meas, name(&format!("{k}p"))),
            )?);
        }
        for k in 4..8 {
            let (p, w) = (name(&format!("{k}p")), name(&format!("{k}w")));
            st.push(stadium_notes(
                Stadium::from_perimeter_width(p, m(meas, p), m(meas, w)),
                notes,
            )?);
        }
        let l = |k: u8| m(meas, name(&format!("{k}L")));
        let heights = [
            l(2) * 0.5,
            l(2) - l(2) * 0.5,
            l(3) - l(2),
            l(4) - l(3),
            l(5),
            l(6) - l(5),
            l(7) - l(6),
        ];
        let dens = [d.upper_arm, d.upper_arm, d.forearm, d.forearm, d.hand, d.hand, d.hand];
        check_heights(&heights, name("4L"))?;
        Ok(std::array::from_fn(|i| stadium_solid(dens[i], &st[i + 1], &st[i], heights[i], variant)))
    };
    let left_arm = arm('a', notes)?;
    let right_arm = arm('b', notes)?;
    // Legs: the hip stadium from Ls0; 1-5 and 7 circles, the heel 6 (anteroposterior), 8 and 9
    // perimeter and width.
    let leg = |side: char, notes: &mut Vec<String>| -> Result<[SolidBody; 9], YeadonError> {
        let name = |s: &str| -> &'static str {
            let full = format!("L{side}{s}");
            MEASUREMENT_NAMES.iter().find(|n| **n == full).copied().unwrap_or("?")
        };
        let hip_p = 2.0 * std::f64::consts::PI * 0.5 * (ls0.radius * ls0.width).abs().sqrt();
        let mut st = vec![Stadium::from_perimeter("Ls0p", hip_p)?];
        for k in 1..6 {
            st.push(Stadium::from_perimeter(
                name(&format!("{k}p")),
                m(meas, name(&format!("{k}p"))),
            )?);
        }
        let (p6, d6) = (name("6p"), name("6d"));
        st.push(
            stadium_notes(Stadium::from_perimeter_width(p6, m(meas, p6), m(meas, d6)), notes)?
                .anteroposterior(),
        );
        st.push(Stadium::from_perimeter(name("7p"), m(meas, name("7p")))?);
        for k in 8..10 {
            let (p, w) = (name(&format!("{k}p")), name(&format!("{k}w")));
            st.push(stadium_notes(
                Stadium::from_perimeter_width(p, m(meas, p), m(meas, w)),
                notes,
            )?);
        }
        let l = |k: u8| m(meas, name(&format!("{k}L")));
        let heights = [
            l(1),
            (l(3) + l(1)) * 0.5 - l(1),
            l(3) - (l(3) + l(1)) * 0.5,
            l(4) - l(3),
            l(5) - l(4),
            l(6),
            (l(8) + l(6)) * 0.5 - l(6),
            l(8) - (l(8) + l(6)) * 0.5,
            l(9) - l(8),
        ];
        let dens =
            [d.thigh, d.thigh, d.thigh, d.lower_leg, d.lower_leg, d.foot, d.foot, d.foot, d.foot];
        check_heights(&heights, name("5L"))?;
        Ok(std::array::from_fn(|i| stadium_solid(dens[i], &st[i + 1], &st[i], heights[i], variant)))
    };
    let left_leg = leg('j', notes)?;
    let right_leg = leg('k', notes)?;
    Ok(Solids {
        torso,
        left_arm,
        right_arm,
        left_leg,
        right_leg,
        shoulder_width: ls4.width,
        hip_width: ls0.thickness + ls0.radius,
    })
}

fn check_heights(heights: &[f64], name: &'static str) -> Result<(), YeadonError> {
    match heights.iter().find(|h| h.is_nan() || **h <= 0.0) {
        Some(h) => Err(YeadonError::Parameter(crate::error::ParameterError::InvalidParameter {
            name,
            value: *h,
            reason:
                "a limb's levels must lie in order along it (each length beyond the one before)",
        })),
        None => Ok(()),
    }
}

/// Yeadon's `euler_123`: $R_x(a) R_y(b) R_z(c)$.
fn euler_123(a: f64, b: f64, c: f64) -> Matrix3<f64> {
    let (sa, ca) = a.sin_cos();
    let (sb, cb) = b.sin_cos();
    let (sc, cc) = c.sin_cos();
    let r1 = Matrix3::new(1.0, 0.0, 0.0, 0.0, ca, -sa, 0.0, sa, ca);
    let r2 = Matrix3::new(cb, 0.0, sb, 0.0, 1.0, 0.0, -sb, 0.0, cb);
    let r3 = Matrix3::new(cc, -sc, 0.0, sc, cc, 0.0, 0.0, 0.0, 1.0);
    r1 * r2 * r3
}

/// $I + m(|d|^2 E - d d^T)$ (yeadon's `parallel_axis`).
fn parallel_axis(i: &Matrix3<f64>, m: f64, d: &Vector3<f64>) -> Matrix3<f64> {
    let (a, b, c) = (d[0], d[1], d[2]);
    let dm = Matrix3::new(
        b * b + c * c,
        -a * b,
        -a * c,
        -a * b,
        c * c + a * a,
        -b * c,
        -a * c,
        -b * c,
        a * a + b * b,
    );
    i + dm * m
}

/// A segment placed in the body: mass, mass centre, inertia about it in the body frame, and the
/// position of its far end.
struct Placed {
    mass: f64,
    centre: Vector3<f64>,
    inertia: Matrix3<f64>,
    end: Vector3<f64>,
}

/// Yeadon's `Segment`: `solids` stacked from `pos` along the segment's $+z$ (`up`) or $-z$,
/// the segment turned by `rot` (segment frame to body frame).
fn place(
    solids: &[SolidBody],
    pos: Vector3<f64>,
    rot: &Matrix3<f64>,
    up: bool,
    variant: Variant,
) -> Placed {
    let axis = rot * Vector3::z();
    // The far end, solid by solid as yeadon sets each solid's position.
    let mut end = pos;
    for s in solids {
        if up {
            end += axis * s.height;
        } else {
            end -= axis * s.height;
        }
    }
    // Each solid's mass centre along the segment's axis, from its origin.
    let mut centres = Vec::with_capacity(solids.len());
    if up {
        let mut p = 0.0;
        for (i, s) in solids.iter().enumerate() {
            if i > 0 {
                p += solids[i - 1].height;
            }
            centres.push(p + s.z);
        }
    } else {
        let mut last = 0.0;
        for s in solids {
            last -= s.height;
            centres.push(last + s.z);
        }
    }
    let mass = solids.iter().fold(0.0, |acc, s| acc + s.mass);
    let moment = solids.iter().zip(&centres).fold(0.0, |acc, (s, z)| acc + s.mass * z);
    let zc = moment / mass;
    let mut rel = Matrix3::zeros();
    for (s, z) in solids.iter().zip(&centres) {
        let i = Matrix3::from_diagonal(&Vector3::new(s.inertia[0], s.inertia[1], s.inertia[2]));
        rel += parallel_axis(&i, s.mass, &Vector3::new(0.0, 0.0, z - zc));
    }
    let centre = pos + rot * Vector3::new(0.0, 0.0, zc);
    let inertia = match variant {
        Variant::Published => rot.transpose() * rel * rot,
        Variant::Corrected => rot * rel * rot.transpose(),
    };
    Placed { mass, centre, inertia, end }
}

impl Human {
    /// The body of `measurements` (left and right limbs averaged), its densities scaled to the
    /// measured total mass when it is given; [`Variant::Published`] reproduces yeadon 2.0.1.
    ///
    /// # Errors
    /// [`YeadonError::Parameter`] naming the measurement at fault: levels out of order (a
    /// solid of height not positive), a stadium whose perimeter is twice its width.
    pub fn new(measurements: &Measurements, variant: Variant) -> Result<Human, YeadonError> {
        let mut meas = measurements.clone();
        let left: Vec<usize> = (21..39).chain(57..76).collect();
        let right: Vec<usize> = (39..57).chain(76..95).collect();
        for (l, r) in left.iter().zip(&right) {
            let avg = 0.5 * (meas.values[*l] + meas.values[*r]);
            meas.values[*l] = avg;
            meas.values[*r] = avg;
        }
        let mut notes = Vec::new();
        let solids = build(&meas, &DEMPSTER, variant, &mut notes)?;
        let mut human = Human { solids, variant, notes, density_scale: 1.0 };
        if let Some(total) = meas.total_mass {
            let ratio = total / human.mass();
            let mut ignored = Vec::new();
            human.solids = build(&meas, &DEMPSTER.scaled(ratio), variant, &mut ignored)?;
            human.density_scale = ratio;
        }
        Ok(human)
    }

    /// The body's mass (kg), the same in every configuration.
    pub fn mass(&self) -> f64 {
        self.mass_properties(&Configuration::default()).mass
    }

    /// What was done beside the measurements as given: impossible stadia taken as circles.
    pub fn notes(&self) -> &[String] {
        &self.notes
    }

    /// The factor applied to Dempster's densities to give the measured mass (1 without one).
    pub fn density_scale(&self) -> f64 {
        self.density_scale
    }

    /// The whole body in the configuration `cfg`: mass, mass centre from the origin (the centre
    /// of `Ls0`) and inertia about the mass centre, in yeadon's body frame (yeadon's
    /// `Human.mass`, `center_of_mass`, `inertia`).
    pub fn mass_properties(&self, cfg: &Configuration) -> MassProperties {
        let s = &self.solids;
        let v = self.variant;
        let a = |n: &str| cfg.get(n);
        let p_rot = euler_123(a("somersault"), a("tilt"), a("twist"));
        let pelvis = place(&s.torso[0..2], Vector3::zeros(), &p_rot, true, v);
        let t_rot = p_rot * euler_123(a("PTsagittalFlexion"), a("PTbending"), 0.0);
        let thorax = place(&s.torso[2..3], pelvis.end, &t_rot, true, v);
        let c_rot = t_rot * euler_123(a("TCsagittalSpinalFlexion"), 0.0, a("TCspinalTorsion"));
        let c_pos = thorax.end;
        let chest = place(&s.torso[3..8], c_pos, &c_rot, true, v);
        let shoulder_height = s.torso[3].height;
        let a1_rot = c_rot * euler_123(a("CA1extension"), a("CA1adduction"), a("CA1rotation"));
        let a1_pos = c_pos + c_rot * Vector3::new(s.shoulder_width / 2.0, 0.0, shoulder_height);
        let a1 = place(&s.left_arm[0..2], a1_pos, &a1_rot, false, v);
        let a2_rot = a1_rot * euler_123(a("A1A2extension"), 0.0, 0.0);
        let a2 = place(&s.left_arm[2..7], a1.end, &a2_rot, false, v);
        let b1_rot = c_rot * euler_123(a("CB1extension"), a("CB1abduction"), a("CB1rotation"));
        let b1_pos = c_pos + c_rot * Vector3::new(-s.shoulder_width / 2.0, 0.0, shoulder_height);
        let b1 = place(&s.right_arm[0..2], b1_pos, &b1_rot, false, v);
        let b2_rot = b1_rot * euler_123(a("B1B2extension"), 0.0, 0.0);
        let b2 = place(&s.right_arm[2..7], b1.end, &b2_rot, false, v);
        let j1_rot = p_rot * euler_123(a("PJ1extension"), a("PJ1adduction"), 0.0);
        let j1_pos = p_rot * Vector3::new(s.hip_width / 2.0, 0.0, 0.0);
        let j1 = place(&s.left_leg[0..3], j1_pos, &j1_rot, false, v);
        let j2_rot = j1_rot * euler_123(a("J1J2flexion"), 0.0, 0.0);
        let j2 = place(&s.left_leg[3..9], j1.end, &j2_rot, false, v);
        let k1_rot = p_rot * euler_123(a("PK1extension"), a("PK1abduction"), 0.0);
        let k1_pos = p_rot * Vector3::new(-s.hip_width / 2.0, 0.0, 0.0);
        let k1 = place(&s.right_leg[0..3], k1_pos, &k1_rot, false, v);
        let k2_rot = k1_rot * euler_123(a("K1K2flexion"), 0.0, 0.0);
        let k2 = place(&s.right_leg[3..9], k1.end, &k2_rot, false, v);
        let segments = [pelvis, thorax, chest, a1, a2, b1, b2, j1, j2, k1, k2];
        let mass = segments.iter().fold(0.0, |acc, g| acc + g.mass);
        let moment = segments.iter().fold(Vector3::zeros(), |acc, g| acc + g.centre * g.mass);
        let centre = moment / mass;
        let mut inertia = Matrix3::zeros();
        for g in &segments {
            inertia += parallel_axis(&g.inertia, g.mass, &(centre - g.centre));
        }
        MassProperties {
            mass,
            centre: [centre[0], centre[1], centre[2]],
            inertia: std::array::from_fn(|i| std::array::from_fn(|j| inertia[(i, j)])),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const JASON: &str = include_str!(
        "../../../../../data/bicycleparameters/riders/Jason/RawData/JasonYeadonMeas.txt"
    );

    #[test]
    fn the_measured_mass_is_kept_in_every_configuration() {
        let meas = Measurements::from_text(JASON).expect("valid");
        assert_eq!(meas.total_mass, Some(83.5));
        let h = Human::new(&meas, Variant::Published).expect("valid");
        assert!((h.mass() - 83.5).abs() < 1e-12, "{}", h.mass());
        let mut cfg = Configuration::default();
        cfg.set("somersault", 0.3);
        cfg.set("J1J2flexion", 1.0);
        let p = h.mass_properties(&cfg);
        assert!((p.mass - 83.5).abs() < 1e-12);
        for i in 0..3 {
            for j in 0..3 {
                assert!((p.inertia[i][j] - p.inertia[j][i]).abs() < 1e-13);
            }
        }
    }

    #[test]
    fn the_corrected_body_turns_as_a_rigid_body() {
        // Turning the whole body by the somersault angle turns its inertia: R I R^T, exactly
        // in the corrected variant, not in yeadon 2.0.1's (its segments turn the other way).
        let meas = Measurements::from_text(JASON).expect("valid");
        let angle = 0.5;
        let mut cfg = Configuration::default();
        cfg.set("somersault", angle);
        let r = euler_123(angle, 0.0, 0.0);
        for (variant, agrees) in [(Variant::Corrected, true), (Variant::Published, false)] {
            let h = Human::new(&meas, variant).expect("valid");
            let i0 = h.mass_properties(&Configuration::default()).inertia;
            let i0 = Matrix3::from_fn(|i, j| i0[i][j]);
            let want = r * i0 * r.transpose();
            let got = h.mass_properties(&cfg).inertia;
            let err = (0..9)
                .map(|k| (got[k / 3][k % 3] - want[(k / 3, k % 3)]).abs())
                .fold(0.0, f64::max);
            assert_eq!(err < 1e-12, agrees, "{variant:?}: {err:e}");
        }
    }

    #[test]
    fn files_are_refused_naming_the_line() {
        let bad = JASON.replace("Ls1L: 17.6", "Ls1L: -17.6");
        assert_eq!(
            Measurements::from_text(&bad).unwrap_err().to_string(),
            "line 29: Ls1L: -17.6 must be positive (`Ls1L: -17.6`)"
        );
        let missing = JASON.replace("Ls1L: 17.6", "");
        assert_eq!(
            Measurements::from_text(&missing).unwrap_err().to_string(),
            "missing Ls1L in the measurement file"
        );
        let unknown = JASON.replace("Ls1L: 17.6", "Ls1L: 17.6\nLs9L: 3");
        assert!(Measurements::from_text(&unknown)
            .unwrap_err()
            .to_string()
            .contains("`Ls9L` is not one of yeadon's 95 measurements"));
        assert!(Measurements::looks_like(JASON));
        assert!(!Measurements::looks_like("mB = 80\nxB = 0.3\n"));
    }
}
