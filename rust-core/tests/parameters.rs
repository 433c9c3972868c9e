//! Validation refuses every bad value with a message naming the parameter
//! (LAMMPS keyword and LIGGGHTS name) and its range.

use granbond::bond::{BondModel, BondParams, PARAMETERS};
use granbond::contact::{VoigtModel, VoigtParams, VOIGT_PARAMETERS};

/// Field names as `Debug` prints them: the table must have one row each.
fn field_names(debug: &str) -> Vec<String> {
    let body = &debug[debug.find('{').unwrap() + 1..debug.rfind('}').unwrap()];
    body.split(", ")
        .map(|f| f.split(':').next().unwrap().trim().to_string())
        .collect()
}

#[test]
fn every_field_has_a_row_in_its_table() {
    let bond: Vec<_> = PARAMETERS.iter().map(|p| p.name.to_string()).collect();
    assert_eq!(bond, field_names(&format!("{:?}", BondParams::default())));
    let voigt: Vec<_> = VOIGT_PARAMETERS.iter().map(|p| p.name.to_string()).collect();
    assert_eq!(voigt, field_names(&format!("{:?}", VoigtParams::default())));
}

#[test]
fn defaults_are_valid() {
    assert!(BondModel::new(BondParams::default()).is_ok());
    assert!(VoigtModel::new(VoigtParams::default()).is_ok());
}

fn refused(p: BondParams) -> (usize, String) {
    let e = BondModel::new(p).expect_err("must be refused");
    (e.parameter, e.message)
}

#[test]
fn bad_values_are_refused_with_the_parameter_named() {
    let d = BondParams::default();
    let cases: Vec<(BondParams, &str, &str)> = vec![
        (
            BondParams { lambda: 0.0, ..d },
            "lambda",
            "radiusMultiplierBondnonlinear",
        ),
        (
            BondParams { k_fn1: -1.0, ..d },
            "k_fn1",
            "stiffnessPerUnitAreaK_fn1",
        ),
        (
            BondParams {
                kc_fn2: f64::NAN,
                ..d
            },
            "kc_fn2",
            "stiffnessPerUnitAreaKc_fn2",
        ),
        (
            BondParams {
                k_ft: f64::INFINITY,
                ..d
            },
            "k_ft",
            "stiffnessPerUnitAreaK_ft",
        ),
        (
            BondParams { eta_fn: 1.0, ..d },
            "eta_fn",
            "dampingNormalForceBondnonlinear",
        ),
        (
            BondParams { eta_tt: -0.1, ..d },
            "eta_tt",
            "dampingTangentialTorqueBondnonlinear",
        ),
        (
            BondParams {
                max_distance: 0.0,
                ..d
            },
            "max_distance",
            "maxDistanceBondnonlinear",
        ),
        (
            BondParams {
                max_sigma: f64::NAN,
                ..d
            },
            "max_sigma",
            "maxSigmaBondnonlinear",
        ),
        (
            BondParams {
                create_distance: -1.0,
                ..d
            },
            "create_distance",
            "createDistanceBondnonlinear",
        ),
        (BondParams { stress_break: 2, ..d }, "stress_break", "stressBreak"),
        (BondParams { bend: -1, ..d }, "bend", "shearTorqueStress"),
        (
            BondParams {
                k_fn1: 2.0,
                ku_fn1: 1.0,
                ..d
            },
            "ku_fn1",
            "stiffnessPerUnitAreaKu_fn1",
        ),
        (
            BondParams {
                k_tt: 2.0,
                ku_tt: 1.0,
                ..d
            },
            "ku_tt",
            "stiffnessPerUnitAreaKu_tt",
        ),
    ];
    for (p, name, liggghts) in cases {
        let (id, message) = refused(p);
        assert_eq!(PARAMETERS[id].name, name, "{message}");
        assert!(message.contains(name) && message.contains(liggghts), "{message}");
        assert!(message.contains("must be"), "states the allowed range: {message}");
    }
}

#[test]
fn infinite_strengths_mean_never_break() {
    let p = BondParams {
        max_sigma: f64::INFINITY,
        max_tau: f64::INFINITY,
        stress_break: 1,
        ..BondParams::default()
    };
    assert!(BondModel::new(p).is_ok());
}

#[test]
fn bad_voigt_values_are_refused_with_the_parameter_named() {
    let d = VoigtParams::default();
    for (p, name) in [
        (VoigtParams { k_n: 0.0, ..d }, "kn"),
        (VoigtParams { mu: -0.1, ..d }, "coefficientFriction"),
        (VoigtParams { mu_r: f64::NAN, ..d }, "coefficientRollingFriction"),
        (VoigtParams { eta_r: -1.0, ..d }, "rollingViscousDamping"),
        (VoigtParams { rolling: 3, ..d }, "rolling_friction voigt"),
    ] {
        let e = VoigtModel::new(p).expect_err("must be refused");
        assert_eq!(VOIGT_PARAMETERS[e.parameter].liggghts_name, name);
        assert!(e.message.contains(name), "{}", e.message);
    }
}

#[test]
fn every_row_sets_its_field_by_either_name_and_reads_it_back() {
    use granbond::parameters::{set_by_name, ParameterKind};
    for (id, row) in PARAMETERS.iter().enumerate() {
        // a value the range admits that differs from the default
        let value = match row.kind() {
            ParameterKind::Switch => 1.0 - row.default_value(),
            ParameterKind::Integer => 41.0,
            ParameterKind::Real => row.default_value().min(0.5) * 0.5 + 0.25,
        };
        for name in [row.name, row.liggghts_name] {
            let mut p = BondParams::default();
            assert_eq!(
                set_by_name("bond/nonlinear", PARAMETERS, &mut p, name, value),
                Ok(id),
                "{name}"
            );
            assert_eq!((row.get)(&p), value, "{name} sets its own field");
            let others = PARAMETERS
                .iter()
                .filter(|r| r.name != row.name)
                .all(|r| (r.get)(&p) == (r.get)(&BondParams::default()));
            assert!(others, "{name} sets no other field");
        }
    }
}

#[test]
fn setting_refuses_unknown_names_and_values_out_of_range_naming_the_parameter() {
    use granbond::parameters::{set_by_name, SetError};
    let mut p = BondParams::default();
    match set_by_name("bond/nonlinear", PARAMETERS, &mut p, "k_fnl", 1.0) {
        Err(SetError::Unknown(m)) => assert!(m.contains("'k_fnl'") && m.contains("k_fn1"), "{m}"),
        other => panic!("unknown name accepted: {other:?}"),
    }
    for (name, value) in [
        ("eta_fn", 1.0),
        ("damping", 0.5),
        ("create_step", 2.5),
        ("lambda", -1.0),
    ] {
        match set_by_name("bond/nonlinear", PARAMETERS, &mut p, name, value) {
            Err(SetError::Refused(e)) => {
                assert_eq!(PARAMETERS[e.parameter].name, name);
                assert!(
                    e.message.contains(name) && e.message.contains("must be"),
                    "{}",
                    e.message
                );
                // a Rust caller reports it as any error: its message
                assert_eq!(e.to_string(), e.message);
                let boxed: Box<dyn std::error::Error> = Box::new(e.clone());
                assert_eq!(boxed.to_string(), e.message);
            }
            other => panic!("{name} = {value} accepted: {other:?}"),
        }
    }
    assert_eq!(
        p,
        BondParams::default(),
        "a refused value leaves the parameters alone"
    );
}

#[test]
fn the_switches_decide_which_values_the_model_reads() {
    let needed = |p: &BondParams| -> Vec<&str> {
        PARAMETERS
            .iter()
            .filter(|r| r.needed(p))
            .map(|r| r.name)
            .collect()
    };
    let d = BondParams::default();
    let distance = needed(&d);
    assert!(distance.contains(&"max_distance") && !distance.contains(&"max_sigma"));
    assert!(distance.contains(&"eta_fn") && distance.contains(&"create_step"));
    let stress = needed(&BondParams {
        stress_break: 1,
        damping: 0,
        create_always: 1,
        ..d
    });
    assert!(stress.contains(&"max_sigma") && stress.contains(&"max_tau"));
    assert!(!stress.contains(&"max_distance") && !stress.contains(&"tension_compression_ratio"));
    assert!(!stress.contains(&"eta_fn") && !stress.contains(&"create_step"));
    let ratio = needed(&BondParams {
        stress_break: 1,
        use_ratio: 1,
        ..d
    });
    assert!(ratio.contains(&"tension_compression_ratio"));
    // smooth damping is damping: the ratios are read with `damping` off
    let smooth = needed(&BondParams {
        damping: 0,
        damping_smooth: 1,
        ..d
    });
    assert!(smooth.contains(&"eta_fn") && smooth.contains(&"smooth_velocity"));
}

#[test]
fn smooth_damping_switches_damping_on() {
    use granbond::bond::features::{DAMPING, SMOOTH};
    let p = BondParams {
        damping: 0,
        damping_smooth: 1,
        eta_fn: 0.1,
        k_fn1: 1e9,
        ku_fn1: 1e9,
        ..BondParams::default()
    };
    let m = BondModel::new(p).unwrap();
    assert_eq!(m.features & (DAMPING | SMOOTH), DAMPING | SMOOTH);
}

/// The reference table of docs/models/bond-nonlinear.md, row by row: each
/// keyword of the core's table is listed there with the core's unit and
/// default, so the documentation cannot drift from the table.
#[test]
fn the_documented_parameter_table_agrees_with_the_core() {
    use granbond::parameters::ParameterKind;
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../docs/models/bond-nonlinear.md"
    ))
    .unwrap();
    let rows: Vec<Vec<String>> = doc
        .lines()
        .skip_while(|l| !l.starts_with("| LAMMPS keyword"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.trim_matches('|')
                .split('|')
                .map(|c| c.trim().to_string())
                .collect()
        })
        .collect();
    assert!(rows.len() > 10, "the table is found");
    for p in PARAMETERS {
        let keyword = format!("`{}`", p.name);
        let row = rows
            .iter()
            .find(|r| r[0].split_whitespace().any(|w| w == keyword))
            .unwrap_or_else(|| panic!("{} is documented", p.name));
        assert_eq!(row[3], p.unit, "unit of {}", p.name);
        let default = p.default_value();
        let documented = match row[5].as_str() {
            "on" => 1.0,
            "off" => 0.0,
            "inf" => f64::INFINITY,
            s => s
                .parse::<f64>()
                .unwrap_or_else(|_| panic!("default of {}: {s}", p.name)),
        };
        assert_eq!(documented, default, "default of {}", p.name);
        if p.kind() == ParameterKind::Switch {
            assert!(
                row[1].contains(&format!("`{}`", p.liggghts_name)),
                "LIGGGHTS switch of {}",
                p.name
            );
        }
    }
}

/// The phrases of a table name its rows, with values the rows admit, and a
/// phrase that follows another follows one that exists.
fn check_phrases<T>(
    table: &[granbond::parameters::ParameterInfo<T>],
    phrases: &[granbond::parameters::Phrase],
) {
    use granbond::parameters::find;
    for p in phrases {
        for name in p.reads {
            assert!(find(table, name).is_some(), "'{}' reads {name}", p.words);
        }
        for (name, value) in p.sets {
            let (_, row) = find(table, name).unwrap_or_else(|| panic!("'{}' sets {name}", p.words));
            assert!(row.range.admits(*value), "'{}' sets {name} = {value}", p.words);
        }
        assert!(
            p.follows.is_empty() || phrases.iter().any(|q| q.words == p.follows),
            "'{}' follows '{}'",
            p.words,
            p.follows
        );
    }
}

#[test]
fn every_phrase_reads_and_sets_rows_of_its_table() {
    check_phrases(PARAMETERS, granbond::bond::PHRASES);
    check_phrases(VOIGT_PARAMETERS, granbond::contact::VOIGT_PHRASES);
}

/// After a phrase's own settings, the model reads every value the phrase
/// reads: a break mode takes the limits of that mode, a tension ratio is
/// read once the phrase switched it on, rolling takes the rolling values.
#[test]
fn a_phrase_reads_the_values_its_settings_make_the_model_read() {
    use granbond::parameters::{find, set_by_name, ParameterInfo, Phrase};
    fn check<T: Default>(model: &str, table: &[ParameterInfo<T>], phrases: &[Phrase]) {
        for p in phrases {
            let mut params = T::default();
            let mut chain: Vec<&Phrase> = vec![p];
            while let Some(before) = phrases
                .iter()
                .find(|q| !chain[0].follows.is_empty() && q.words == chain[0].follows)
            {
                chain.insert(0, before);
            }
            for q in chain {
                for (name, value) in q.sets {
                    set_by_name(model, table, &mut params, name, *value).unwrap();
                }
            }
            for name in p.reads {
                assert!(
                    find(table, name).unwrap().1.needed(&params),
                    "'{}': {name} unread",
                    p.words
                );
            }
        }
    }
    check("bond/nonlinear", PARAMETERS, granbond::bond::PHRASES);
    check("voigt", VOIGT_PARAMETERS, granbond::contact::VOIGT_PHRASES);
}

#[test]
fn a_break_mode_sets_the_stress_and_bpm_switches() {
    let mode = |words: &str| {
        granbond::bond::PHRASES
            .iter()
            .find(|p| p.words == words)
            .map(|p| p.sets.to_vec())
    };
    assert_eq!(
        mode("break distance"),
        Some(vec![("stress_break", 0.0), ("bpm_break", 0.0)])
    );
    assert_eq!(
        mode("break stress"),
        Some(vec![("stress_break", 1.0), ("bpm_break", 0.0)])
    );
    assert_eq!(
        mode("break bpm"),
        Some(vec![("stress_break", 0.0), ("bpm_break", 1.0)])
    );
    assert_eq!(mode("create_step"), Some(vec![("create_always", 0.0)]));
}

#[test]
fn every_voigt_row_has_its_part() {
    let parts: Vec<&str> = granbond::contact::VOIGT_PARTS
        .iter()
        .map(|(name, _)| *name)
        .collect();
    let rows: Vec<&str> = VOIGT_PARAMETERS.iter().map(|r| r.name).collect();
    assert_eq!(parts, rows);
}

/// LIGGGHTS's stock tangential and rolling models read the spring and
/// dashpot from the engine's contact data, so `model voigt` must have read
/// the rows it hands them.
#[test]
fn model_voigt_reads_the_tangential_rows_it_hands_to_stock_models() {
    use granbond::contact::{ContactPart, VOIGT_SUB_MODELS};
    let normal = &VOIGT_SUB_MODELS[ContactPart::Normal as usize];
    assert_eq!(normal.words, "model voigt");
    for handed in ["k_n", "gamma_n", "k_t", "gamma_t"] {
        let (_, part) = granbond::contact::VOIGT_PARTS
            .iter()
            .find(|(n, _)| *n == handed)
            .unwrap();
        assert!(normal.reads.contains(part), "model voigt does not read {handed}");
    }
}

/// Each sub-model reads its own part and is the one a deck names by the
/// words of the switch that says its part is present.
#[test]
fn each_voigt_sub_model_reads_its_part_and_names_its_presence_switch() {
    use granbond::contact::{ContactPart, VOIGT_SUB_MODELS};
    use granbond::parameters::LiggghtsSource;
    for (k, sub) in VOIGT_SUB_MODELS.iter().enumerate() {
        assert_eq!(sub.part as usize, k, "{}", sub.words);
        assert!(sub.reads.contains(&sub.part), "{}", sub.words);
    }
    for (row, (_, part)) in VOIGT_PARAMETERS.iter().zip(granbond::contact::VOIGT_PARTS) {
        if row.source == LiggghtsSource::Fixed {
            assert_eq!(
                row.liggghts_name, VOIGT_SUB_MODELS[*part as usize].words,
                "{}",
                row.name
            );
        }
    }
    let rolling = &VOIGT_SUB_MODELS[ContactPart::Rolling as usize];
    assert_eq!(rolling.reads, &[ContactPart::Rolling]);
}

/// Rolling resistance reads exactly the rolling part's values.
#[test]
fn the_rolling_part_is_what_rolling_resistance_reads() {
    use granbond::contact::ContactPart;
    let off = VoigtParams {
        rolling: 0,
        ..VoigtParams::default()
    };
    for (row, (_, part)) in VOIGT_PARAMETERS.iter().zip(granbond::contact::VOIGT_PARTS) {
        let only_with_rolling = !row.needed(&off) && row.needed(&VoigtParams::default());
        if row.name != "rolling" {
            assert_eq!(only_with_rolling, *part == ContactPart::Rolling, "{}", row.name);
        }
    }
}

#[test]
fn finite_values_beyond_the_magnitudes_the_models_form_are_refused_by_name() {
    use granbond::parameters::{set_by_name, SetError};
    for (name, value) in [("k_ft", 1e300), ("lambda", 1e-300), ("max_sigma", 1e101)] {
        let mut p = BondParams::default();
        match set_by_name("bond/nonlinear", PARAMETERS, &mut p, name, value) {
            Err(SetError::Refused(e)) => {
                assert_eq!(PARAMETERS[e.parameter].name, name);
                assert!(
                    e.message.contains(name) && e.message.contains("in magnitude"),
                    "{}",
                    e.message
                );
            }
            other => panic!("{name} {value} accepted: {other:?}"),
        }
    }
    // 0 and inf where the range takes them are not magnitudes
    let mut p = BondParams::default();
    assert!(set_by_name("bond/nonlinear", PARAMETERS, &mut p, "k_ft", 0.0).is_ok());
    assert!(set_by_name("bond/nonlinear", PARAMETERS, &mut p, "max_tau", f64::INFINITY).is_ok());
    let huge = BondParams {
        k_tn: 1e200,
        ku_tn: 1e200,
        ..p
    };
    let e = huge.validate().expect_err("refused");
    assert_eq!(PARAMETERS[e.parameter].name, "k_tn");
}

#[test]
fn smoothing_velocities_default_to_the_same_physical_quantities_in_every_unit_style() {
    // (unit style, metres and seconds in its units of length and time)
    for (style, metre, second) in [
        ("si", 1.0, 1.0),
        ("cgs", 1e-2, 1.0),
        ("micro", 1e-6, 1e-6),
        ("nano", 1e-9, 1e-9),
    ] {
        let p = BondParams::default_in_units(style);
        let (v, w) = (
            p.smooth_velocity * metre / second,
            p.smooth_angular_velocity / second,
        );
        assert!(
            (v - 1e-5).abs() <= 1e-20 && (w - 1e-3).abs() <= 1e-18,
            "{style}: {v} m/s, {w} rad/s"
        );
        let smooth = BondParams {
            damping_smooth: 1,
            ..p
        };
        assert!(BondModel::new(smooth).is_ok(), "{style}");
    }
    // lj has no physical scale: no default, so smooth damping needs them given
    let lj = BondParams::default_in_units("lj");
    assert!(
        BondModel::new(lj).is_ok(),
        "without smooth damping they are not read"
    );
    let (id, message) = refused(BondParams {
        damping_smooth: 1,
        ..lj
    });
    assert_eq!(PARAMETERS[id].name, "smooth_velocity", "{message}");
    assert!(message.contains("must be given"), "{message}");
    let given = BondParams {
        damping_smooth: 1,
        smooth_velocity: 1e-5,
        smooth_angular_velocity: 1e-3,
        ..lj
    };
    assert!(BondModel::new(given).is_ok());
}

/// Where a deck does not give `contact_under_bond`, the contact goes on
/// under the bond exactly where the law keeps some of its loads there
/// (INL's code, the linear bond), whatever the row held before.
#[test]
fn contact_under_bond_by_the_law_goes_on_where_the_law_keeps_contact_loads() {
    // (the linear bond refuses inl_compatible)
    for (linear, inl) in [(0, 0), (0, 1), (1, 0)] {
        for before in [0, 1] {
            let mut p = BondParams {
                inl_compatible: inl,
                contact_under_bond: before,
                ..if linear == 1 {
                    BondParams::linear_default_in_units("si")
                } else {
                    BondParams::default_in_units("si")
                }
            };
            p.contact_under_bond_by_law();
            let m = BondModel::new(p).expect("a valid law");
            assert_eq!(
                m.contact_goes_on_under_bond(),
                m.keeps_contact_loads() || m.keeps_contact_tangential(),
                "linear {linear}, inl_compatible {inl}, before {before}"
            );
            assert_eq!(p.contact_under_bond, i32::from(linear == 1 || inl == 1));
        }
    }
}

/// What the contact does under a bond is a row of the bond table, set by
/// either engine's name: off for `bond/nonlinear` (the contact held at
/// zero under the bond, afresh at the break), on for the linear bond, whose
/// law keeps the contact's loads under the bond; both values build a model
/// that says so.
#[test]
fn the_contact_under_the_bond_is_a_row_with_each_law_s_default() {
    use granbond::parameters::set_by_name;
    let row = PARAMETERS
        .iter()
        .find(|r| r.name == "contact_under_bond")
        .expect("a row of the table");
    assert_eq!(row.liggghts_name, "contactUnderBond");
    let nonlinear = BondParams::default_in_units("si");
    let linear = BondParams::linear_default_in_units("si");
    assert!(!BondModel::new(nonlinear).unwrap().contact_goes_on_under_bond());
    let m = BondModel::new(linear).unwrap();
    assert!(m.contact_goes_on_under_bond() && m.keeps_contact_loads());
    for (p, name) in [(nonlinear, "contact_under_bond"), (linear, "contactUnderBond")] {
        for value in [1.0, 0.0] {
            let mut q = p;
            set_by_name("bond/nonlinear", PARAMETERS, &mut q, name, value).unwrap();
            let m = BondModel::new(q).expect("either value, either law");
            assert_eq!(m.contact_goes_on_under_bond(), value == 1.0, "{name} {value}");
        }
    }
}
