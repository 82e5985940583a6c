//! Solver tests: each expected value is worked out by hand in the comment beside it.

use super::*;

fn num(p: &mut Problem, name: &str) -> VarId {
    p.add_var(
        name,
        VarKind::Number {
            integer: false,
            lo: None,
            hi: None,
        },
    )
}

fn le(p: &mut Problem, expr: Linear, strict: bool, origin: u32) -> ConstraintId {
    let rel = if strict { Relation::Lt } else { Relation::Le };
    p.add(ConstraintKind::Linear { expr, rel }, Strength::Hard, origin)
}

fn eq(p: &mut Problem, expr: Linear, strength: Strength, origin: u32) -> ConstraintId {
    p.add(
        ConstraintKind::Linear {
            expr,
            rel: Relation::Eq,
        },
        strength,
        origin,
    )
}

/// `x - c`
fn minus(x: VarId, c: f64) -> Linear {
    Linear::var(x).add_scaled(&Linear::constant(c), -1.0)
}

fn number(s: &Solution, v: VarId) -> f64 {
    match s.values[v.0 as usize] {
        Value::Number(x) => x,
        ref other => panic!("not a number: {other:?}"),
    }
}

#[test]
fn a_range_is_sampled_inside_and_reproducibly() {
    let mut p = Problem::default();
    let w = num(&mut p, "w");
    // 1.95 <= w <= 2.1
    le(&mut p, minus(w, 1.95).scale(-1.0), false, 0);
    le(&mut p, minus(w, 2.1), false, 1);
    let a = Solver::new(&p, 7).unwrap().finish().unwrap();
    let b = Solver::new(&p, 7).unwrap().finish().unwrap();
    let x = number(&a, w);
    assert!((1.95..=2.1).contains(&x), "{x}");
    assert_eq!(a, b);
    let others: Vec<f64> = (0..8)
        .map(|seed| number(&Solver::new(&p, seed).unwrap().finish().unwrap(), w))
        .collect();
    assert!(
        others.iter().any(|y| *y != x),
        "different seeds give different values"
    );
}

#[test]
fn conflicting_bounds_name_both_constraints() {
    let mut p = Problem::default();
    let x = num(&mut p, "x");
    let c0 = le(&mut p, minus(x, 5.0).scale(-1.0), true, 0); // x > 5
    let y = num(&mut p, "y");
    let _unrelated = le(&mut p, minus(y, 1.0), false, 1);
    let c2 = le(&mut p, minus(x, 2.0), true, 2); // x < 2
    match Solver::new(&p, 0) {
        Err(SolveError::Unsat { constraints }) => assert_eq!(constraints, vec![c0, c2]),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_conflict_through_a_chain_names_every_link() {
    // a >= 10, b == a + 1, b <= 5: a >= 10 gives b >= 11 > 5.
    let mut p = Problem::default();
    let a = num(&mut p, "a");
    let b = num(&mut p, "b");
    let c0 = le(&mut p, minus(a, 10.0).scale(-1.0), false, 0);
    let c1 = eq(
        &mut p,
        Linear::var(b).add_scaled(&minus(a, -1.0), -1.0),
        Strength::Hard,
        1,
    );
    let c2 = le(&mut p, minus(b, 5.0), false, 2);
    match Solver::new(&p, 0) {
        Err(SolveError::Unsat { constraints }) => assert_eq!(constraints, vec![c0, c1, c2]),
        other => panic!("{other:?}"),
    }
}

#[test]
fn linked_variables_stay_consistent_after_sampling() {
    // b == a + 1, 0 <= a <= 1: whatever a is drawn, b is a + 1.
    let mut p = Problem::default();
    let a = num(&mut p, "a");
    let b = num(&mut p, "b");
    le(&mut p, Linear::var(a).scale(-1.0), false, 0);
    le(&mut p, minus(a, 1.0), false, 1);
    eq(
        &mut p,
        Linear::var(b).add_scaled(&minus(a, -1.0), -1.0),
        Strength::Hard,
        2,
    );
    for seed in 0..5 {
        let s = Solver::new(&p, seed).unwrap().finish().unwrap();
        assert!((number(&s, b) - number(&s, a) - 1.0).abs() < 1e-12);
    }
}

#[test]
fn integers_take_whole_values_and_uint_starts_at_zero() {
    let mut p = Problem::default();
    let n = p.add_var(
        "n",
        VarKind::Number {
            integer: true,
            lo: Some(0.0),
            hi: None,
        },
    );
    // n < 3 over uint: n in {0, 1, 2}.
    le(&mut p, minus(n, 3.0), true, 0);
    for seed in 0..20 {
        let v = number(&Solver::new(&p, seed).unwrap().finish().unwrap(), n);
        assert!(v == 0.0 || v == 1.0 || v == 2.0, "{v}");
    }
    // n < 0 over uint has no solution; the type's bound has no constraint behind it.
    let mut q = p.clone();
    le(&mut q, Linear::var(n), true, 1);
    assert!(matches!(Solver::new(&q, 0), Err(SolveError::Unsat { .. })));
}

#[test]
fn a_default_is_overridden_by_a_hard_constraint_and_hints_the_sample() {
    // default w in [1.6, 2.1]; hard w >= 1.95: the default is dropped, w lands in [1.95, 2.1].
    let mut p = Problem::default();
    let w = num(&mut p, "w");
    let d0 = p.add(
        ConstraintKind::Linear {
            expr: minus(w, 1.6).scale(-1.0),
            rel: Relation::Le,
        },
        Strength::Default,
        0,
    );
    let d1 = p.add(
        ConstraintKind::Linear {
            expr: minus(w, 2.1),
            rel: Relation::Le,
        },
        Strength::Default,
        1,
    );
    le(&mut p, minus(w, 1.95).scale(-1.0), false, 2);
    for seed in 0..20 {
        let s = Solver::new(&p, seed).unwrap().finish().unwrap();
        let x = number(&s, w);
        assert!((1.95..=2.1).contains(&x), "{x}");
        assert_eq!(s.dropped_defaults, vec![d0, d1]);
    }
}

#[test]
fn a_default_applies_when_nothing_else_constrains_the_field() {
    let mut p = Problem::default();
    let x = num(&mut p, "x");
    eq(&mut p, minus(x, 3.0), Strength::Default, 0);
    let s = Solver::new(&p, 1).unwrap().finish().unwrap();
    assert_eq!(number(&s, x), 3.0);
    assert!(s.dropped_defaults.is_empty());
}

#[test]
fn enum_membership_and_exclusion() {
    // category in [bus, truck] (members 1, 2 of 6), category != bus: truck.
    let mut p = Problem::default();
    let c = p.add_var("category", VarKind::Enum { count: 6 });
    p.add(
        ConstraintKind::Member {
            var: c,
            set: vec![1, 2],
            negated: false,
        },
        Strength::Hard,
        0,
    );
    p.add(
        ConstraintKind::Member {
            var: c,
            set: vec![1],
            negated: true,
        },
        Strength::Hard,
        1,
    );
    let s = Solver::new(&p, 3).unwrap().finish().unwrap();
    assert_eq!(s.values[c.0 as usize], Value::Member(2));
    // and == car conflicts with both.
    let mut q = p.clone();
    let c2 = q.add(
        ConstraintKind::Member {
            var: c,
            set: vec![0],
            negated: false,
        },
        Strength::Hard,
        2,
    );
    match Solver::new(&q, 0) {
        Err(SolveError::Unsat { constraints }) => {
            assert!(constraints.contains(&ConstraintId(0)) && constraints.contains(&c2))
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn equal_enum_variables_share_a_member_and_unequal_ones_differ() {
    let mut p = Problem::default();
    let a = p.add_var("a", VarKind::Enum { count: 3 });
    let b = p.add_var("b", VarKind::Enum { count: 3 });
    let c = p.add_var("c", VarKind::Enum { count: 3 });
    p.add(
        ConstraintKind::Member {
            var: a,
            set: vec![2],
            negated: false,
        },
        Strength::Hard,
        0,
    );
    p.add(
        ConstraintKind::SameMember {
            a,
            b,
            negated: false,
        },
        Strength::Hard,
        1,
    );
    p.add(
        ConstraintKind::SameMember {
            a: b,
            b: c,
            negated: true,
        },
        Strength::Hard,
        2,
    );
    for seed in 0..10 {
        let s = Solver::new(&p, seed).unwrap().finish().unwrap();
        assert_eq!(s.values[b.0 as usize], Value::Member(2));
        assert_ne!(s.values[c.0 as usize], Value::Member(2));
    }
}

#[test]
fn numeric_inequality_is_met_by_resampling() {
    // n in {0, 1}, n != 0: n = 1 (propagation cannot remove an inner point; sampling can).
    let mut p = Problem::default();
    let n = p.add_var(
        "n",
        VarKind::Number {
            integer: true,
            lo: Some(0.0),
            hi: Some(1.0),
        },
    );
    p.add(
        ConstraintKind::Linear {
            expr: Linear::var(n),
            rel: Relation::Ne,
        },
        Strength::Hard,
        0,
    );
    for seed in 0..10 {
        assert_eq!(
            number(&Solver::new(&p, seed).unwrap().finish().unwrap(), n),
            1.0
        );
    }
}

#[test]
fn text_equality() {
    let mut p = Problem::default();
    let t = p.add_var("t", VarKind::Text);
    p.add(
        ConstraintKind::Text {
            var: t,
            value: "a".into(),
            negated: false,
        },
        Strength::Hard,
        0,
    );
    let s = Solver::new(&p, 0).unwrap().finish().unwrap();
    assert_eq!(s.values[0], Value::Text("a".into()));
    p.add(
        ConstraintKind::Text {
            var: t,
            value: "b".into(),
            negated: false,
        },
        Strength::Hard,
        1,
    );
    assert!(matches!(Solver::new(&p, 0), Err(SolveError::Unsat { .. })));
}

#[test]
fn a_float_cycle_stops_propagating() {
    // x < y, y < x over unbounded then bounded floats: no hang, and a conflict once bounded.
    let mut p = Problem::default();
    let x = num(&mut p, "x");
    let y = num(&mut p, "y");
    le(
        &mut p,
        Linear::var(x).add_scaled(&Linear::var(y), -1.0),
        true,
        0,
    );
    le(
        &mut p,
        Linear::var(y).add_scaled(&Linear::var(x), -1.0),
        true,
        1,
    );
    let _ = Solver::new(&p, 0).and_then(|s| s.finish());
    le(&mut p, Linear::var(x).scale(-1.0), false, 2);
    le(&mut p, minus(x, 1.0), false, 3);
    assert!(Solver::new(&p, 0).and_then(|s| s.finish()).is_err());
}

#[test]
fn a_constant_constraint_that_fails_is_its_own_conflict() {
    let mut p = Problem::default();
    let c = le(&mut p, Linear::constant(1.0), false, 0); // 1 <= 0
    assert_eq!(
        Solver::new(&p, 0).unwrap_err(),
        SolveError::Unsat {
            constraints: vec![c]
        }
    );
}
