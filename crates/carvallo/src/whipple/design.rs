//! The Carvallo–Whipple bicycle's parameters with names a researcher reads: [`BicycleDesign`],
//! made of two [`Wheel`]s and two [`Body`]s (the rear frame with its rider, the front frame with
//! its handlebar), beside the flat array of [`WhippleParams`].
//!
//! The array in the order of [`PARAM_NAMES`] stays the layout the generated evaluators and the
//! sweeps work on; a [`BicycleDesign`] converts to and from it field by field
//! ([`BicycleDesign::to_array`], [`BicycleDesign::from_array`]) and is validated by the same
//! checks, whose errors name the benchmark key (`"mB"`, not `rear_frame.mass`;
//! [`BicycleDesign::field_path`] translates). Every field's documentation gives its symbol in
//! Table 1 of the 2007 benchmark (Meijaard, Papadopoulos, Ruina, Schwab, Proc. R. Soc. A 463)
//! and its SI unit. Axes are the benchmark's: $x$ forward, $z$ down, origin at the rear contact
//! point, so the centres of mass above the ground have negative $z$.
//!
//! # Example
//! ```
//! use carvallo::whipple::{BicycleDesign, Whipple};
//!
//! let mut design = BicycleDesign::benchmark();
//! design.rear_frame.mass = 90.0;
//! let bike = Whipple::from_design(design)?;
//! assert_eq!(bike.params().get("mB"), Some(90.0));
//!
//! design.front_wheel.radius = -0.35;
//! let err = Whipple::from_design(design).unwrap_err();
//! assert_eq!(err.to_string(), "invalid rF -0.35: must not be negative");
//! assert_eq!(BicycleDesign::field_path("rF"), Some("front_wheel.radius"));
//! # Ok::<(), carvallo::whipple::WhippleError>(())
//! ```

use super::params::{WhippleError, WhippleParams, PARAM_NAMES};

/// A wheel, symmetric about its axle: the benchmark's rear wheel R or front wheel F.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wheel {
    /// Radius $r_R$ / $r_F$ (m).
    pub radius: f64,
    /// Mass $m_R$ / $m_F$ (kg).
    pub mass: f64,
    /// Moment of inertia about a diameter, $I_{Rxx} = I_{Rzz}$ / $I_{Fxx} = I_{Fzz}$ (kg m²).
    pub ixx: f64,
    /// Moment of inertia about the axle, $I_{Ryy}$ / $I_{Fyy}$ (kg m²).
    pub iyy: f64,
}

/// A rigid body symmetric about the bicycle's plane: the benchmark's rear frame B (with the
/// rider rigidly attached) or front frame H (fork and handlebar). The inertias are about the
/// body's centre of mass, in the benchmark's axes in the upright reference configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Centre of mass, forward of the rear contact, $x_B$ / $x_H$ (m).
    pub x: f64,
    /// Centre of mass, vertical (down positive, so negative above the ground), $z_B$ / $z_H$ (m).
    pub z: f64,
    /// Mass $m_B$ / $m_H$ (kg).
    pub mass: f64,
    /// Moment of inertia $I_{Bxx}$ / $I_{Hxx}$ (kg m²).
    pub ixx: f64,
    /// Moment of inertia $I_{Byy}$ / $I_{Hyy}$ (kg m²).
    pub iyy: f64,
    /// Moment of inertia $I_{Bzz}$ / $I_{Hzz}$ (kg m²).
    pub izz: f64,
    /// Product of inertia $I_{Bxz}$ / $I_{Hxz}$ (kg m²).
    pub ixz: f64,
}

/// The Carvallo–Whipple bicycle's 25 parameters and $g$ by name (Table 1 of the 2007
/// benchmark): the geometry, gravity and the four bodies.
///
/// It is plain data: any values can be written into it; [`WhippleParams::from_design`] (or
/// [`Whipple::from_design`](super::Whipple::from_design)) validates them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BicycleDesign {
    /// Wheelbase $w$, from the rear contact to the front contact (m).
    pub wheelbase: f64,
    /// Trail $c$, from the front contact back to where the steer axis meets the ground (m).
    pub trail: f64,
    /// Steer axis tilt $\lambda$ from the vertical, $\pi/2$ minus the head angle (rad).
    pub steer_axis_tilt: f64,
    /// Gravitational acceleration $g$ (m/s²).
    pub gravity: f64,
    /// The rear wheel R ($r_R$, $m_R$, $I_{Rxx}$, $I_{Ryy}$).
    pub rear_wheel: Wheel,
    /// The rear frame B with its rider ($x_B$, $z_B$, $m_B$, $I_{Bxx}$, $I_{Byy}$, $I_{Bzz}$,
    /// $I_{Bxz}$).
    pub rear_frame: Body,
    /// The front frame H, fork and handlebar ($x_H$, $z_H$, $m_H$, $I_{Hxx}$, $I_{Hyy}$,
    /// $I_{Hzz}$, $I_{Hxz}$).
    pub front_frame: Body,
    /// The front wheel F ($r_F$, $m_F$, $I_{Fxx}$, $I_{Fyy}$).
    pub front_wheel: Wheel,
}

/// The field of [`BicycleDesign`] holding each benchmark key, in the order of [`PARAM_NAMES`].
pub const FIELD_PATHS: [&str; 26] = [
    "wheelbase",
    "trail",
    "steer_axis_tilt",
    "gravity",
    "rear_wheel.radius",
    "rear_wheel.mass",
    "rear_wheel.ixx",
    "rear_wheel.iyy",
    "rear_frame.x",
    "rear_frame.z",
    "rear_frame.mass",
    "rear_frame.ixx",
    "rear_frame.iyy",
    "rear_frame.izz",
    "rear_frame.ixz",
    "front_frame.x",
    "front_frame.z",
    "front_frame.mass",
    "front_frame.ixx",
    "front_frame.iyy",
    "front_frame.izz",
    "front_frame.ixz",
    "front_wheel.radius",
    "front_wheel.mass",
    "front_wheel.ixx",
    "front_wheel.iyy",
];

impl BicycleDesign {
    /// The benchmark bicycle of the 2007 paper.
    pub fn benchmark() -> BicycleDesign {
        WhippleParams::benchmark().design()
    }

    /// The design whose parameters, in the order of [`PARAM_NAMES`], are `v` (not validated).
    pub fn from_array(v: &[f64; 26]) -> BicycleDesign {
        let wheel = |k: usize| Wheel { radius: v[k], mass: v[k + 1], ixx: v[k + 2], iyy: v[k + 3] };
        let body = |k: usize| Body {
            x: v[k],
            z: v[k + 1],
            mass: v[k + 2],
            ixx: v[k + 3],
            iyy: v[k + 4],
            izz: v[k + 5],
            ixz: v[k + 6],
        };
        BicycleDesign {
            wheelbase: v[0],
            trail: v[1],
            steer_axis_tilt: v[2],
            gravity: v[3],
            rear_wheel: wheel(4),
            rear_frame: body(8),
            front_frame: body(15),
            front_wheel: wheel(22),
        }
    }

    /// The parameters in the order of [`PARAM_NAMES`], the layout of
    /// [`WhippleParams::from_values`].
    pub fn to_array(&self) -> [f64; 26] {
        let (r, b, h, f) = (self.rear_wheel, self.rear_frame, self.front_frame, self.front_wheel);
        [
            self.wheelbase,
            self.trail,
            self.steer_axis_tilt,
            self.gravity,
            r.radius,
            r.mass,
            r.ixx,
            r.iyy,
            b.x,
            b.z,
            b.mass,
            b.ixx,
            b.iyy,
            b.izz,
            b.ixz,
            h.x,
            h.z,
            h.mass,
            h.ixx,
            h.iyy,
            h.izz,
            h.ixz,
            f.radius,
            f.mass,
            f.ixx,
            f.iyy,
        ]
    }

    /// Reads and validates a parameter file in the anchors format, as
    /// [`WhippleParams::from_toml_str`].
    ///
    /// # Errors
    /// [`WhippleError`] naming the benchmark key and value at fault.
    pub fn from_toml_str(text: &str) -> Result<BicycleDesign, WhippleError> {
        WhippleParams::from_toml_str(text).map(|p| p.design())
    }

    /// The design as a `[parameters]` table in the anchors format, every number in round-trip
    /// form, which [`from_toml_str`](Self::from_toml_str) reads back exactly when the design is
    /// valid.
    pub fn to_toml_string(&self) -> String {
        let mut s = String::from("[parameters]\n");
        for (key, value) in PARAM_NAMES.iter().zip(self.to_array()) {
            s.push_str(&format!("{key} = {value:?}\n"));
        }
        s
    }

    /// The field holding the benchmark key `key` (`"mB"` gives `"rear_frame.mass"`), if it is
    /// one of [`PARAM_NAMES`]: to translate the key named by a [`WhippleError`].
    pub fn field_path(key: &str) -> Option<&'static str> {
        PARAM_NAMES.iter().position(|k| *k == key).map(|i| FIELD_PATHS[i])
    }
}

impl From<&WhippleParams> for BicycleDesign {
    fn from(p: &WhippleParams) -> BicycleDesign {
        BicycleDesign::from_array(p.values())
    }
}

impl From<WhippleParams> for BicycleDesign {
    fn from(p: WhippleParams) -> BicycleDesign {
        BicycleDesign::from_array(p.values())
    }
}

impl TryFrom<BicycleDesign> for WhippleParams {
    type Error = WhippleError;

    fn try_from(design: BicycleDesign) -> Result<WhippleParams, WhippleError> {
        WhippleParams::from_design(design)
    }
}

impl WhippleParams {
    /// Validates `design` with the checks of [`from_values`](Self::from_values) on its
    /// [array](BicycleDesign::to_array).
    ///
    /// # Errors
    /// As [`from_values`](Self::from_values): a [`WhippleError::Parameter`] naming the benchmark
    /// key of the field at fault (see [`BicycleDesign::field_path`]).
    pub fn from_design(design: BicycleDesign) -> Result<WhippleParams, WhippleError> {
        WhippleParams::from_values(design.to_array())
    }

    /// The parameters by name.
    pub fn design(&self) -> BicycleDesign {
        BicycleDesign::from_array(self.values())
    }
}
