//! The mechanics engine: rolling systems derived from a *description* (frames by successive
//! simple rotations, rigid bodies, wheels rolling without slipping on flat ground, gravity and
//! joint torques) instead of vector algebra written by hand for each model.
//!
//! A [`Model`] names its parameters, its generalised coordinates (independent, dependent — fixed
//! by a holonomic constraint —, or ignorable: absent from the equations, like the heading and
//! the wheels' rotations), its frames, points, bodies and wheels. [`kane::derive`] turns it into
//! the equations of motion for the independent speeds $u$,
//! $$M(q)\,\dot u = f(q, u),$$
//! with the dependent speeds and their accelerations eliminated through the velocity
//! constraints; [`lagrange::derive`] gives the same equations by Carvallo's modified Lagrange
//! method (memoir n° 71–72), so that every model is derived twice and the two routes check each
//! other.
//!
//! Conventions. The ground frame `N` has its z axis *down* (the benchmark's axes: x forward,
//! y right, z down) and the ground is the plane z = 0. Every vector is written in the
//! *working frame* `W`: the ground frame turned about its vertical by the model's heading
//! coordinate when it has one (so that the equations do not contain the heading; `W` rotates
//! with the heading rate), the ground frame itself otherwise. The generalised speeds are the
//! coordinates' rates (named `<coordinate>d`) and the components on `W`'s horizontal axes of the
//! velocity of the *root point* (the point every position chain starts from, on the ground).
//!
//! Every quantity is handed over *named*: the sines and cosines, each level of a rotated vector,
//! the partial velocities, the constraint coefficients, the dependent rates are formulas of
//! their own to which later formulas refer by name (see [`crate::emit::emit_program`]), as the
//! hand derivations do, so the equations never expand.

pub mod kane;
pub mod kinematics;
pub mod lagrange;
pub mod linear;
pub mod store;

use std::collections::BTreeSet;
use std::fmt;

use symbolica::atom::Atom;

use crate::cas::var;

/// A coordinate's role in the equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// An independent coordinate: its rate is an independent speed.
    Independent,
    /// Fixed by a holonomic constraint (a wheel's contact height); its rate is a dependent speed.
    Dependent,
    /// Absent from the equations (the heading, a wheel's rotation about its axle); its rate is
    /// independent unless `dependent_rate` says the constraints give it.
    Ignorable {
        /// Whether the velocity constraints give its rate (the heading's, a front wheel's).
        dependent_rate: bool,
    },
}

/// One generalised coordinate.
#[derive(Clone, Debug)]
pub struct Coordinate {
    /// Its name (an IR name: letters, digits, underscores); the rate is `<name>d`.
    pub name: String,
    /// What it means, with its unit.
    pub description: String,
    /// Its role.
    pub kind: Kind,
}

impl Coordinate {
    /// The name of its rate, `<name>d`.
    pub fn speed(&self) -> String {
        format!("{}d", self.name)
    }
}

/// An axis of a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// The first axis.
    X,
    /// The second axis.
    Y,
    /// The third axis.
    Z,
}

impl Axis {
    /// The index of the axis (0, 1, 2).
    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        }
    }

    /// The unit vector of the axis, in its own frame's components.
    pub fn unit(self) -> [Atom; 3] {
        let mut v = [Atom::num(0), Atom::num(0), Atom::num(0)];
        v[self.index()] = Atom::num(1);
        v
    }
}

/// The angle of a simple rotation.
#[derive(Clone, Debug)]
pub enum Angle {
    /// A generalised coordinate, by name.
    Coordinate(String),
    /// A constant angle: a parameter, by name, with a sign (the steering axis' tilt λ or −λ).
    Parameter {
        /// The parameter's name.
        name: String,
        /// Whether the angle is minus the parameter.
        negated: bool,
    },
}

/// One simple rotation of a frame relative to the previous one.
#[derive(Clone, Debug)]
pub struct Rotation {
    /// The rotation's axis (an axis of both frames).
    pub axis: Axis,
    /// The rotation's angle.
    pub angle: Angle,
}

/// A reference frame: its parent rotated by successive simple rotations (body-fixed).
#[derive(Clone, Debug)]
pub struct Frame {
    /// Its name.
    pub name: String,
    /// The frame it is oriented from (`N`, the ground, or an earlier frame).
    pub parent: String,
    /// The rotations from the parent, in order.
    pub rotations: Vec<Rotation>,
}

/// A point: an earlier point plus a vector fixed in a frame (its components in that frame).
#[derive(Clone, Debug)]
pub struct Point {
    /// Its name.
    pub name: String,
    /// The point it is placed from (the root point, or an earlier point).
    pub from: String,
    /// The frame in which the offset is fixed.
    pub frame: String,
    /// The offset's components in that frame.
    pub offset: [Atom; 3],
}

/// A rigid body: mass, mass centre, inertia about the mass centre in the body's frame.
#[derive(Clone, Debug)]
pub struct Body {
    /// Its name.
    pub name: String,
    /// The frame fixed in the body.
    pub frame: String,
    /// The point that is its mass centre.
    pub centre: String,
    /// Its mass.
    pub mass: Atom,
    /// Its inertia tensor about the mass centre, in the frame's axes (symmetric).
    pub inertia: [[Atom; 3]; 3],
}

/// A wheel: a body of revolution about an axle fixed in a carrier frame, spinning about it by a
/// coordinate, rolling without slipping on the ground (a knife edge).
#[derive(Clone, Debug)]
pub struct Wheel {
    /// Its name.
    pub name: String,
    /// The frame that carries the axle.
    pub carrier: String,
    /// The point that is its centre (fixed in the carrier).
    pub centre: String,
    /// The axle's axis of the carrier frame.
    pub axle: Axis,
    /// The coordinate of its rotation relative to the carrier.
    pub spin: String,
    /// Its radius.
    pub radius: Atom,
    /// Its mass.
    pub mass: Atom,
    /// Its moment of inertia about a diameter.
    pub diametral: Atom,
    /// Its moment of inertia about the axle.
    pub axial: Atom,
    /// A frame whose axis points from the centre to the contact point, when one exists (the
    /// rear wheel's lean frame); otherwise the engine writes the downward direction in the
    /// wheel's plane, $(\hat z - a_z a)/\sqrt{1 - a_z^2}$.
    pub down: Option<(String, Axis)>,
    /// Whether the contact is the root point (the root point is then on the ground by
    /// construction: no holonomic constraint, and the vertical constraint row vanishes).
    pub at_root: bool,
}

/// A torque between two frames (or wheels) about an axis of the second (of a wheel's carrier),
/// the generalised force of a joint.
#[derive(Clone, Debug)]
pub struct Torque {
    /// Its name (an input of the model, or the name of a spring's formula).
    pub name: String,
    /// The magnitude: an input symbol or an expression (a spring and a damper).
    pub value: Atom,
    /// The frame or wheel that receives the reaction (`N` for the ground).
    pub from: String,
    /// The frame or wheel that receives the torque.
    pub to: String,
    /// The axis of `to` (of its carrier, for a wheel) about which it acts.
    pub axis: Axis,
}

/// A whole description.
#[derive(Clone, Debug)]
pub struct Model {
    /// The model name.
    pub name: String,
    /// Parameter names, in order.
    pub params: Vec<String>,
    /// Input names beyond the state (torques), in order.
    pub inputs: Vec<String>,
    /// The coordinates.
    pub coordinates: Vec<Coordinate>,
    /// The coordinate that turns the working frame about the vertical (the heading), if any.
    pub heading: Option<String>,
    /// The root point's name (on the ground; its velocity components on the working frame's x
    /// and y axes are the speeds `<root>_u`, `<root>_v`).
    pub root: String,
    /// The frames, parents first (`N` is the ground and is not listed).
    pub frames: Vec<Frame>,
    /// The points, in order of definition.
    pub points: Vec<Point>,
    /// The rigid bodies (wheels excluded).
    pub bodies: Vec<Body>,
    /// The wheels.
    pub wheels: Vec<Wheel>,
    /// The torques.
    pub torques: Vec<Torque>,
    /// The gravitational acceleration (along the ground's z axis, down).
    pub gravity: Atom,
}

/// A description that cannot be derived, naming the item at fault.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DescriptionError {
    /// A name refers to nothing declared before it.
    Unknown {
        /// What kind of item refers ("frame H", "body B", ...).
        item: String,
        /// What it refers to.
        missing: String,
    },
    /// A body or wheel without mass or inertia.
    NoInertia {
        /// The body or wheel.
        item: String,
    },
    /// A name declared twice or not an IR name.
    BadName {
        /// The name.
        name: String,
        /// Why.
        reason: String,
    },
    /// The constraints do not give the dependent speeds.
    Constraints {
        /// What is wrong.
        reason: String,
    },
}

impl fmt::Display for DescriptionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DescriptionError::Unknown { item, missing } => {
                write!(f, "{item} refers to `{missing}`, which is not declared before it")
            }
            DescriptionError::NoInertia { item } => {
                write!(f, "{item} has no mass or no inertia: every body needs both")
            }
            DescriptionError::BadName { name, reason } => write!(f, "bad name `{name}`: {reason}"),
            DescriptionError::Constraints { reason } => write!(f, "constraints: {reason}"),
        }
    }
}

impl std::error::Error for DescriptionError {}

fn is_ir_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

impl Model {
    /// The coordinate named `name`.
    pub fn coordinate(&self, name: &str) -> Option<&Coordinate> {
        self.coordinates.iter().find(|c| c.name == name)
    }

    /// The independent speeds, in the coordinates' order.
    pub fn independent_speeds(&self) -> Vec<String> {
        self.coordinates
            .iter()
            .filter(|c| {
                matches!(c.kind, Kind::Independent | Kind::Ignorable { dependent_rate: false })
            })
            .map(Coordinate::speed)
            .collect()
    }

    /// The dependent speeds: the root point's two velocity components, then the rates of the
    /// dependent coordinates and of the ignorable ones the constraints give.
    pub fn dependent_speeds(&self) -> Vec<String> {
        let mut out = vec![format!("{}_u", self.root), format!("{}_v", self.root)];
        out.extend(
            self.coordinates
                .iter()
                .filter(|c| {
                    matches!(c.kind, Kind::Dependent | Kind::Ignorable { dependent_rate: true })
                })
                .map(Coordinate::speed),
        );
        out
    }

    /// The coordinates that appear in the equations (independent and dependent), in order.
    pub fn configuration(&self) -> Vec<String> {
        self.coordinates
            .iter()
            .filter(|c| matches!(c.kind, Kind::Independent | Kind::Dependent))
            .map(|c| c.name.clone())
            .collect()
    }

    /// Checks that every name refers to something declared before it, that every body has a
    /// mass and an inertia, and that names are unique IR names; the first fault is named.
    pub fn validate(&self) -> Result<(), DescriptionError> {
        let mut names = BTreeSet::new();
        let mut declare = |name: &str| {
            if !is_ir_name(name) {
                return Err(DescriptionError::BadName {
                    name: name.to_string(),
                    reason: "not an IR name (a letter, then letters, digits or _)".into(),
                });
            }
            if !names.insert(name.to_string()) {
                return Err(DescriptionError::BadName {
                    name: name.to_string(),
                    reason: "declared twice".into(),
                });
            }
            Ok(())
        };
        for p in self.params.iter().chain(&self.inputs) {
            declare(p)?;
        }
        for c in &self.coordinates {
            declare(&c.name)?;
        }
        let coordinate = |item: &str, name: &str| {
            self.coordinate(name).map(|_| ()).ok_or_else(|| DescriptionError::Unknown {
                item: item.to_string(),
                missing: name.to_string(),
            })
        };
        if let Some(h) = &self.heading {
            coordinate("the heading", h)?;
        }
        let mut frames: Vec<&str> = vec!["N"];
        for f in &self.frames {
            let item = format!("frame {}", f.name);
            if !frames.contains(&f.parent.as_str()) {
                return Err(DescriptionError::Unknown { item, missing: f.parent.clone() });
            }
            for r in &f.rotations {
                match &r.angle {
                    Angle::Coordinate(c) => coordinate(&item, c)?,
                    Angle::Parameter { name, .. } => {
                        if !self.params.contains(name) {
                            return Err(DescriptionError::Unknown { item, missing: name.clone() });
                        }
                    }
                }
            }
            declare(&f.name)?;
            frames.push(&f.name);
        }
        let frame = |item: &str, name: &str| {
            if frames.contains(&name) {
                Ok(())
            } else {
                Err(DescriptionError::Unknown { item: item.to_string(), missing: name.to_string() })
            }
        };
        let mut points: Vec<&str> = vec![&self.root];
        for p in &self.points {
            let item = format!("point {}", p.name);
            if !points.contains(&p.from.as_str()) {
                return Err(DescriptionError::Unknown { item, missing: p.from.clone() });
            }
            frame(&item, &p.frame)?;
            declare(&p.name)?;
            points.push(&p.name);
        }
        let point = |item: &str, name: &str| {
            if points.contains(&name) {
                Ok(())
            } else {
                Err(DescriptionError::Unknown { item: item.to_string(), missing: name.to_string() })
            }
        };
        for b in &self.bodies {
            let item = format!("body {}", b.name);
            frame(&item, &b.frame)?;
            point(&item, &b.centre)?;
            let diagonal_zero = (0..3).any(|k| b.inertia[k][k].is_zero());
            if b.mass.is_zero() || diagonal_zero {
                return Err(DescriptionError::NoInertia { item });
            }
        }
        for w in &self.wheels {
            let item = format!("wheel {}", w.name);
            frame(&item, &w.carrier)?;
            point(&item, &w.centre)?;
            coordinate(&item, &w.spin)?;
            if let Some((f, _)) = &w.down {
                frame(&item, f)?;
            }
            if w.mass.is_zero() || w.diametral.is_zero() || w.axial.is_zero() {
                return Err(DescriptionError::NoInertia { item });
            }
        }
        for t in &self.torques {
            let item = format!("torque {}", t.name);
            for end in [&t.from, &t.to] {
                if !self.wheels.iter().any(|w| &w.name == end) {
                    frame(&item, end)?;
                }
            }
        }
        if self.wheels.iter().filter(|w| w.at_root).count() > 1 {
            return Err(DescriptionError::Constraints {
                reason: "more than one wheel's contact is the root point".into(),
            });
        }
        Ok(())
    }
}

/// `formulas` reordered so that each follows every formula of the list it uses, otherwise in
/// their first order (a depth-first visit in list order).
fn in_dependency_order(formulas: Vec<crate::Formula>) -> Vec<crate::Formula> {
    let index: std::collections::BTreeMap<String, usize> =
        formulas.iter().enumerate().map(|(i, f)| (f.name.clone(), i)).collect();
    let uses: Vec<Vec<usize>> = formulas
        .iter()
        .map(|f| store::symbols_of(&f.expr).iter().filter_map(|s| index.get(s).copied()).collect())
        .collect();
    let mut placed = vec![false; formulas.len()];
    let mut order = Vec::with_capacity(formulas.len());
    for start in 0..formulas.len() {
        // An explicit stack: (formula, whether its uses have been pushed).
        let mut stack = vec![(start, false)];
        while let Some((i, expanded)) = stack.pop() {
            if placed[i] {
                continue;
            }
            if expanded {
                placed[i] = true;
                order.push(i);
            } else {
                stack.push((i, true));
                stack.extend(uses[i].iter().rev().filter(|&&j| !placed[j]).map(|&j| (j, false)));
            }
        }
    }
    let mut slots: Vec<Option<crate::Formula>> = formulas.into_iter().map(Some).collect();
    order.into_iter().map(|i| slots[i].take().expect("placed once")).collect()
}

/// Shorthand for a parameter or input symbol.
pub fn sym(name: &str) -> Atom {
    var(name)
}

/// A coordinate (shorthand for descriptions).
pub fn coordinate(name: &str, description: &str, kind: Kind) -> Coordinate {
    Coordinate { name: name.into(), description: description.into(), kind }
}

/// A simple rotation by a coordinate (shorthand for descriptions).
pub fn rot(axis: Axis, coordinate: &str) -> Rotation {
    Rotation { axis, angle: Angle::Coordinate(coordinate.into()) }
}

/// A frame from its parent by `rotations` (shorthand for descriptions).
pub fn frame(name: &str, parent: &str, rotations: Vec<Rotation>) -> Frame {
    Frame { name: name.into(), parent: parent.into(), rotations }
}

/// A point from an earlier one by an offset fixed in `frame` (shorthand for descriptions).
pub fn point(name: &str, from: &str, frame: &str, offset: [Atom; 3]) -> Point {
    Point { name: name.into(), from: from.into(), frame: frame.into(), offset }
}

/// Kane's part of [`derivation`], the program a model generates (Carvallo's modified Lagrange
/// equations are derived too, and checked against Kane's by the derivation tests), with one
/// check: the rolling constraints' only redundant row is the vertical one of the wheel whose
/// contact is the root point (its height does not depend on the coordinates), the case of every
/// single-track vehicle; [`kane_derivation_expecting`] names other rows.
pub fn kane_derivation(m: &Model, source: &str) -> Result<crate::Derivation, DescriptionError> {
    let root = m.wheels.iter().find(|w| w.at_root).map_or("", |w| w.name.as_str());
    kane_derivation_expecting(m, source, &[&format!("{root} vertical")])
}

/// [`kane_derivation`] for a description whose rolling constraints have other redundant rows
/// (two wheels on one axle state the axle's lateral motion twice): the check `redundant_rows`
/// holds when the rows the engine dropped, each named with the reason (it vanishes
/// identically, or is implied by the others at a seeded point), are exactly `expected` (row
/// labels such as `"R vertical"`, `"L lateral"`), in any order.
pub fn kane_derivation_expecting(
    m: &Model,
    source: &str,
    expected: &[&str],
) -> Result<crate::Derivation, DescriptionError> {
    let (d, kane_len, redundant) = derivation(m, source)?;
    let label = |r: &String| r.split(':').next().unwrap_or("").to_string();
    let mut found: Vec<String> = redundant.iter().map(label).collect();
    let mut want: Vec<String> = expected.iter().map(|s| s.to_string()).collect();
    found.sort();
    want.sort();
    // The derived list of redundant rows without its first row: the check must then fail.
    let perturbed = found.first().map(|first| crate::Perturbed {
        what: format!("the derived list of redundant rows without its first row ({first})"),
        holds: found[1..] == want[..],
    });
    let check = crate::Check {
        perturbed,
        section: "34".into(),
        id: "redundant_rows".into(),
        statement: format!(
            "the rolling constraints' redundant rows, dropped and named, are exactly: {}",
            expected.join(", ")
        ),
        holds: found == want,
        detail: redundant.join("; "),
    };
    let mut formulas = d.formulas;
    formulas.truncate(kane_len);
    Ok(crate::Derivation { formulas, checks: vec![check], ..d })
}

/// The equations of a description by both routes, as a [`crate::Derivation`]: every named
/// quantity, the dependent speeds, the contact heights and their derivatives in the dependent
/// coordinates (for Newton's method), Kane's `M_<ui>_<uj>` and `f_<ui>`, the energy, then the
/// modified Lagrange equations' `L_M_<ui>_<uj>` and `L_f_<ui>`. Inputs: the independent and
/// dependent coordinates, the independent speeds and the model's inputs. Also returns the number
/// of formulas that make up Kane's equations (the first ones), and the rows found redundant.
pub fn derivation(
    m: &Model,
    source: &str,
) -> Result<(crate::Derivation, usize, Vec<String>), DescriptionError> {
    derivation_of(m, source, false)
}

/// [`derivation`], and for every independent speed that is a coordinate's rate the plain
/// Lagrange term $\mathrm{d}T/\mathrm{d}q$ that Carvallo's correction replaces, named
/// `L_q_<speed>` (for comparison with the correction `L_c_<speed>`; it costs the partial
/// derivatives of every partial velocity, so only a derivation that compares asks for it).
pub fn derivation_with_plain_lagrange(
    m: &Model,
    source: &str,
) -> Result<(crate::Derivation, usize, Vec<String>), DescriptionError> {
    derivation_of(m, source, true)
}

fn derivation_of(
    m: &Model,
    source: &str,
    plain: bool,
) -> Result<(crate::Derivation, usize, Vec<String>), DescriptionError> {
    let mut st = store::Store::new(&m.name, "");
    let k = kane::derive(m, &mut st)?;
    for (wheel, h) in &k.heights {
        for c in m.coordinates.iter().filter(|c| c.kind == Kind::Dependent) {
            let dh = st.partial(h, &c.name);
            let name = format!("{wheel}_contact_height_d{}", c.name);
            // The chain rule names the partial of a named height itself.
            if dh != var(&name) {
                let what = format!(
                    "d {wheel}_contact_height / d {}: Newton's step for the dependent coordinate",
                    c.name
                );
                let _ = st.put(&name, &what, dh);
            }
        }
    }
    let u: Vec<Atom> = k.independent.iter().map(|s| var(s)).collect();
    let mut kinetic = Atom::num(0);
    for i in 0..u.len() {
        for j in 0..u.len() {
            kinetic += &k.m[i][j] * &u[i] * &u[j];
        }
    }
    let _ = st.put(
        "energy",
        "total energy: kinetic energy (1/2 u^T M u) plus gravity's potential (J)",
        kinetic / Atom::num(2) + &k.potential,
    );
    let kane_len = st.formulas.len();
    let _ = lagrange::derive(m, &mut st, &k, plain);
    let mut inputs = m.configuration();
    inputs.extend(k.independent.iter().cloned());
    inputs.extend(m.inputs.iter().cloned());
    let mut redundant = k.redundant.clone();
    redundant.extend(k.vanishing.iter().map(|r| format!("{r}: vanishes identically")));
    // A rate can be named before the formula of a dependent speed it contains: order each part
    // (Kane's, then Lagrange's) so that every formula follows the ones it uses.
    let lagrange_part = st.formulas.split_off(kane_len);
    let mut formulas = in_dependency_order(std::mem::take(&mut st.formulas));
    formulas.extend(in_dependency_order(lagrange_part));
    Ok((
        crate::Derivation {
            model: m.name.clone(),
            source: source.to_string(),
            params: m.params.clone(),
            inputs,
            formulas,
            checks: Vec::new(),
            nominal: Vec::new(),
            horner_schemes: Vec::new(),
        },
        kane_len,
        redundant,
    ))
}

/// A small description's equations with every named quantity substituted: $M$ and $f$ of
/// $M\dot u = f$ by each route, as closed forms in the parameters, the coordinates' sines and
/// cosines (`sin(phi)`, …) and the independent speeds.
pub struct ClosedForm {
    /// The independent speeds, the order of the rows and columns.
    pub speeds: Vec<String>,
    /// Kane's mass matrix (full, symmetric) and forcing.
    pub kane: (Vec<Vec<Atom>>, Vec<Atom>),
    /// The modified Lagrange equations' mass matrix and forcing.
    pub lagrange: (Vec<Vec<Atom>>, Vec<Atom>),
    /// The total energy.
    pub energy: Atom,
}

/// The equations of `m` by both routes in closed form ([`ClosedForm`]): the formulas of
/// [`derivation`] substituted into each other in their order. Meant for systems small enough to
/// be written out (the rolling hoop, the unicycle), whose closed forms a derivation compares with
/// the memoir's and solves.
pub fn closed_form(m: &Model) -> Result<ClosedForm, DescriptionError> {
    use symbolica::atom::AtomCore;
    let (d, _, _) = derivation(m, "")?;
    let mut known: std::collections::BTreeMap<String, Atom> = std::collections::BTreeMap::new();
    for f in &d.formulas {
        let mut e = f.expr.clone();
        for s in store::symbols_of(&f.expr) {
            if let Some(v) = known.get(&s) {
                e = e.replace(var(&s).to_pattern()).with(v.to_pattern());
            }
        }
        known.insert(f.name.clone(), e);
    }
    let speeds = m.independent_speeds();
    let get = |name: String| {
        known.get(&name).cloned().ok_or_else(|| DescriptionError::Constraints {
            reason: format!("the derivation names no {name}"),
        })
    };
    let system = |prefix: &str| -> Result<(Vec<Vec<Atom>>, Vec<Atom>), DescriptionError> {
        let mut mass = vec![vec![Atom::num(0); speeds.len()]; speeds.len()];
        let mut forcing = Vec::with_capacity(speeds.len());
        for (i, ui) in speeds.iter().enumerate() {
            for (j, uj) in speeds.iter().enumerate().skip(i) {
                let e = get(format!("{prefix}M_{ui}_{uj}"))?;
                mass[i][j] = e.clone();
                mass[j][i] = e;
            }
            forcing.push(get(format!("{prefix}f_{ui}"))?);
        }
        Ok((mass, forcing))
    };
    Ok(ClosedForm {
        kane: system("")?,
        lagrange: system("L_")?,
        energy: get("energy".into())?,
        speeds,
    })
}
