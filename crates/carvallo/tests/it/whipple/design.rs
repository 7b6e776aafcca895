//! The parameters by name, [`BicycleDesign`]: the round trips array ↔ design ↔ TOML, the
//! constructors taking a design, and validation errors naming the benchmark key of the field
//! at fault.

use carvallo::whipple::nonlinear::WhippleNonlinear;
use carvallo::whipple::parameter_text::UncertainParams;
use carvallo::whipple::{
    BicycleDesign, Whipple, WhippleError, WhippleParams, BENCHMARK_TOML, FIELD_PATHS, PARAM_NAMES,
};
use carvallo::ParameterError;

#[test]
fn the_benchmark_reads_by_name() {
    let d = BicycleDesign::benchmark();
    assert_eq!((d.wheelbase, d.trail, d.gravity), (1.02, 0.08, 9.81));
    assert_eq!(d.steer_axis_tilt, std::f64::consts::PI / 10.0);
    assert_eq!((d.rear_wheel.radius, d.rear_wheel.mass), (0.3, 2.0));
    assert_eq!((d.rear_wheel.ixx, d.rear_wheel.iyy), (0.0603, 0.12));
    assert_eq!((d.rear_frame.x, d.rear_frame.z, d.rear_frame.mass), (0.3, -0.9, 85.0));
    assert_eq!(
        (d.rear_frame.ixx, d.rear_frame.iyy, d.rear_frame.izz, d.rear_frame.ixz),
        (9.2, 11.0, 2.8, 2.4)
    );
    assert_eq!((d.front_frame.x, d.front_frame.z, d.front_frame.mass), (0.9, -0.7, 4.0));
    assert_eq!(
        (d.front_frame.ixx, d.front_frame.iyy, d.front_frame.izz, d.front_frame.ixz),
        (0.05892, 0.06, 0.00708, -0.00756)
    );
    assert_eq!((d.front_wheel.radius, d.front_wheel.mass), (0.35, 3.0));
    assert_eq!((d.front_wheel.ixx, d.front_wheel.iyy), (0.1405, 0.28));
}

#[test]
fn every_field_is_its_benchmark_key() {
    // Distinct values in every slot: the array position k holds k + 1.
    let array: [f64; 26] = std::array::from_fn(|k| k as f64 + 1.0);
    let d = BicycleDesign::from_array(&array);
    assert_eq!(d.to_array(), array);
    for (k, key) in PARAM_NAMES.iter().enumerate() {
        assert_eq!(BicycleDesign::field_path(key), Some(FIELD_PATHS[k]));
        // The field named by the path holds the value of the key.
        let v = match FIELD_PATHS[k].split_once('.') {
            None => match FIELD_PATHS[k] {
                "wheelbase" => d.wheelbase,
                "trail" => d.trail,
                "steer_axis_tilt" => d.steer_axis_tilt,
                "gravity" => d.gravity,
                other => panic!("unexpected field {other}"),
            },
            Some((part, field)) => {
                let wheel = match part {
                    "rear_wheel" => Some(d.rear_wheel),
                    "front_wheel" => Some(d.front_wheel),
                    _ => None,
                };
                let body = match part {
                    "rear_frame" => Some(d.rear_frame),
                    "front_frame" => Some(d.front_frame),
                    _ => None,
                };
                match (wheel, body, field) {
                    (Some(w), _, "radius") => w.radius,
                    (Some(w), _, "mass") => w.mass,
                    (Some(w), _, "ixx") => w.ixx,
                    (Some(w), _, "iyy") => w.iyy,
                    (_, Some(b), "x") => b.x,
                    (_, Some(b), "z") => b.z,
                    (_, Some(b), "mass") => b.mass,
                    (_, Some(b), "ixx") => b.ixx,
                    (_, Some(b), "iyy") => b.iyy,
                    (_, Some(b), "izz") => b.izz,
                    (_, Some(b), "ixz") => b.ixz,
                    _ => panic!("unexpected field {part}.{field}"),
                }
            }
        };
        assert_eq!(v, array[k], "{key} is {}", FIELD_PATHS[k]);
    }
    assert_eq!(BicycleDesign::field_path("mass"), None);
}

#[test]
fn array_design_and_toml_round_trip() {
    let p = WhippleParams::benchmark();
    let d = p.design();
    assert_eq!(d, BicycleDesign::from(&p));
    assert_eq!(&d.to_array(), p.values());
    assert_eq!(WhippleParams::from_design(d), Ok(p.clone()));
    assert_eq!(WhippleParams::try_from(d), Ok(p.clone()));
    // TOML: the design written and read back is bit-identical, and so is the benchmark file.
    let text = d.to_toml_string();
    assert_eq!(BicycleDesign::from_toml_str(&text), Ok(d));
    assert_eq!(BicycleDesign::from_toml_str(BENCHMARK_TOML), Ok(d));
    assert_eq!(WhippleParams::from_toml_str(&text), Ok(p.clone()));
    // Random valid designs round-trip through all three forms.
    let mut rng = carvallo::numerics::rng::SplitMix64(7);
    for _ in 0..200 {
        let q = p.perturbed(&mut rng, 0.2);
        let d = q.design();
        let back = BicycleDesign::from_toml_str(&d.to_toml_string()).expect("valid");
        assert_eq!(back.to_array().map(f64::to_bits), q.values().map(f64::to_bits));
        assert_eq!(WhippleParams::from_design(back), Ok(q));
    }
}

#[test]
fn constructors_take_a_design() {
    let d = BicycleDesign::benchmark();
    let p = WhippleParams::benchmark();
    let bike = Whipple::from_design(d).expect("valid");
    assert_eq!(bike, Whipple::new(p.clone()));
    assert_eq!(bike.design(), d);
    assert_eq!(WhippleNonlinear::from_design(d).expect("valid").params(), &p);
    let u = UncertainParams::exact(p);
    assert_eq!(u.design(), d);
    assert_eq!(u.sigma_design(), BicycleDesign::from_array(&[0.0; 26]));
}

#[test]
fn a_bad_field_is_named_by_its_benchmark_key() {
    let mut d = BicycleDesign::benchmark();
    d.rear_frame.mass = -85.0;
    let err = Whipple::from_design(d).unwrap_err();
    assert_eq!(err.to_string(), "invalid mB -85.0: must be positive");
    assert_eq!(
        err,
        WhippleError::from(ParameterError::InvalidParameter {
            name: "mB",
            value: -85.0,
            reason: "must be positive"
        })
    );
    assert_eq!(BicycleDesign::field_path("mB"), Some("rear_frame.mass"));

    let mut d = BicycleDesign::benchmark();
    d.steer_axis_tilt = 2.0;
    assert_eq!(
        WhippleParams::from_design(d).unwrap_err().to_string(),
        "invalid lambda 2.0: must lie strictly between -pi/2 and pi/2"
    );
    let mut d = BicycleDesign::benchmark();
    d.front_wheel.iyy = 1.0;
    assert_eq!(
        WhippleNonlinear::from_design(d).unwrap_err().to_string(),
        "invalid IFyy 1.0: exceeds 2 IFxx (triangle inequality of the wheel's moments)"
    );
    let mut d = BicycleDesign::benchmark();
    d.gravity = f64::NAN;
    assert_eq!(
        WhippleParams::try_from(d).unwrap_err().to_string(),
        "invalid g NaN: must be finite"
    );
}
