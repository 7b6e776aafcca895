//! The side view of a bicycle for a geometry drawing: the points every drawing of the bicycle
//! (the command line's `carvallo plot geometry`, the report, Python's `carvallo.geometry` and
//! `plot_geometry`) draws, computed once here so that they all draw the same points.
//!
//! Coordinates are those of the benchmark (Meijaard et al. 2007, §2) in the plane of
//! symmetry, upright: $x$ forward from the rear contact, and the height $h = -z$ above the
//! ground (the benchmark's $z$ points down). The rear wheel of radius $r_R$ touches the ground
//! at $(0, 0)$ with its centre at $(0, r_R)$; the front wheel of radius $r_F$ touches it at
//! $(w, 0)$ with its centre at $(w, r_F)$. The steer axis, tilted back by $\lambda$ from the
//! vertical, meets the ground at $(w + c, 0)$, the trail $c$ ahead of the front contact; its
//! points are $(w + c - t\sin\lambda,\ t\cos\lambda)$ for $t \ge 0$. The front hub lies at
//! $t_F = c\sin\lambda + r_F\cos\lambda$ along it and at the fork offset
//! $e = r_F\sin\lambda - c\cos\lambda$ ahead of it.
//!
//! The frame is drawn schematically (the parameters do not give its tubes): a triangle from
//! the rear hub to the foot of the front hub on the steer axis and to the top of the axis,
//! drawn up to the height of the higher of the front wheel's top and the front frame's mass
//! centre; the fork from the front hub to its foot on the axis. The mass centres are the
//! rear wheel's (its hub), the rear frame's $(x_B, -z_B)$, the front frame's $(x_H, -z_H)$, the
//! front wheel's (its hub), a rider's when one is given apart from the bicycle, and the whole
//! system's.

use super::parameter_text::Rider;
use super::WhippleParams;

/// One body's mass centre in the side view.
#[derive(Clone, Debug, PartialEq)]
pub struct MassCentre {
    /// `rear wheel`, `rear frame`, `front frame`, `front wheel`, `rider` or `whole bicycle`.
    pub name: &'static str,
    /// The body's mass (kg).
    pub mass: f64,
    /// Where it is: $(x, h)$ (m).
    pub at: [f64; 2],
}

/// The points of a side view (see the module docs); every point is $(x, h)$ (m).
#[derive(Clone, Debug, PartialEq)]
pub struct SideView {
    /// The rear wheel's contact with the ground, $(0, 0)$.
    pub rear_contact: [f64; 2],
    /// The rear hub, $(0, r_R)$.
    pub rear_hub: [f64; 2],
    /// $r_R$ (m).
    pub rear_radius: f64,
    /// The front wheel's contact with the ground, $(w, 0)$.
    pub front_contact: [f64; 2],
    /// The front hub, $(w, r_F)$.
    pub front_hub: [f64; 2],
    /// $r_F$ (m).
    pub front_radius: f64,
    /// The steer axis from the ground, $(w + c, 0)$, to its drawn top.
    pub steer_axis: [[f64; 2]; 2],
    /// The trail: from the front contact to the steer axis's point on the ground; its length
    /// is $c$.
    pub trail: [[f64; 2]; 2],
    /// The fork: from the front hub to its foot on the steer axis (length the fork offset).
    pub fork: [[f64; 2]; 2],
    /// The schematic rear frame: rear hub, foot of the front hub on the steer axis, top of the
    /// axis.
    pub frame: [[f64; 2]; 3],
    /// The mass centres: rear wheel, rear frame, front frame, front wheel, the rider (when
    /// given apart) and the whole system.
    pub mass_centres: Vec<MassCentre>,
}

impl SideView {
    /// The side view of the bicycle `p`, with the rider `rider` drawn apart from the rear frame
    /// when given (its mass centre $(x_B, -z_B)$ of the rider file, counted in the whole
    /// system's). `p` is the bicycle without that rider: a bicycle whose rear frame already
    /// includes its rider is drawn with the joint mass centre as the rear frame's.
    pub fn new(p: &WhippleParams, rider: Option<&Rider>) -> SideView {
        let v = |name: &str| p.get(name).unwrap_or(f64::NAN);
        let (w, c, lambda, r_r, r_f) = (v("w"), v("c"), v("lambda"), v("rR"), v("rF"));
        let (sin, cos) = lambda.sin_cos();
        let on_axis = |t: f64| [w + c - t * sin, t * cos];
        let t_hub = c * sin + r_f * cos;
        let front_frame = [v("xH"), -v("zH")];
        // The axis reaches the higher of the wheel's top and the front frame's mass centre.
        let t_top = (2.0 * r_f).max(front_frame[1]) / cos;
        let mut mass_centres = vec![
            MassCentre { name: "rear wheel", mass: v("mR"), at: [0.0, r_r] },
            MassCentre { name: "rear frame", mass: v("mB"), at: [v("xB"), -v("zB")] },
            MassCentre { name: "front frame", mass: v("mH"), at: front_frame },
            MassCentre { name: "front wheel", mass: v("mF"), at: [w, r_f] },
        ];
        if let Some(r) = rider {
            let [m, x, _, z, ..] = r.values;
            mass_centres.push(MassCentre { name: "rider", mass: m, at: [x, -z] });
        }
        let total: f64 = mass_centres.iter().map(|b| b.mass).sum();
        let moment = |k: usize| mass_centres.iter().map(|b| b.mass * b.at[k]).sum::<f64>();
        let whole = [moment(0) / total, moment(1) / total];
        mass_centres.push(MassCentre { name: "whole bicycle", mass: total, at: whole });
        SideView {
            rear_contact: [0.0, 0.0],
            rear_hub: [0.0, r_r],
            rear_radius: r_r,
            front_contact: [w, 0.0],
            front_hub: [w, r_f],
            front_radius: r_f,
            steer_axis: [on_axis(0.0), on_axis(t_top)],
            trail: [[w, 0.0], on_axis(0.0)],
            fork: [[w, r_f], on_axis(t_hub)],
            frame: [[0.0, r_r], on_axis(t_hub), on_axis(t_top)],
            mass_centres,
        }
    }

    /// The fork offset $e = r_F\sin\lambda - c\cos\lambda$ (m): the front hub's distance ahead
    /// of the steer axis.
    pub fn fork_offset(&self) -> f64 {
        // The axis's unit vector u = (−sin λ, cos λ) and the forward normal (u_h, −u_x).
        let [[gx, gh], [tx, th]] = self.steer_axis;
        let len = (tx - gx).hypot(th - gh);
        let (ux, uh) = ((tx - gx) / len, (th - gh) / len);
        let [[x0, h0], [x1, h1]] = self.fork;
        (x0 - x1) * uh - (h0 - h1) * ux
    }

    /// Every point drawn, for the extent of a figure: the wheels' boxes, the axis, the frame
    /// and the mass centres.
    pub fn extent(&self) -> ([f64; 2], [f64; 2]) {
        let mut pts: Vec<[f64; 2]> = vec![
            [self.rear_hub[0] - self.rear_radius, 0.0],
            [self.rear_hub[0], 2.0 * self.rear_radius],
            [self.front_hub[0] + self.front_radius, 0.0],
            [self.front_hub[0], 2.0 * self.front_radius],
        ];
        pts.extend(self.steer_axis);
        pts.extend(self.frame);
        pts.extend(self.mass_centres.iter().map(|m| m.at));
        let fold = |k: usize| {
            pts.iter()
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[a, b], p| [a.min(p[k]), b.max(p[k])])
        };
        (fold(0), fold(1))
    }
}
