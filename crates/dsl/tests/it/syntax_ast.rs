//! The typed AST view over the syntax tree, read on the domain model's examples (seed 000,
//! §8.7) and on declarations whose parts are known; and the rendering of diagnostics.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use dsl::syntax::ast::{
    Argument, BinaryOp, CompositionOperator, ConstraintQualifier, EventCondition, Expr, Item,
    LiteralValue, Member, MethodImpl, Number, Type,
};
use dsl::syntax::{parse, AstNode, SyntaxKind};

fn seed(name: &str) -> String {
    let path = format!(
        "{}/tests/files/syntax/{name}.osc",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(path).unwrap()
}

#[test]
fn wide_car_constraints_read_through_the_ast() {
    let parse = parse(&seed("seed_wide_car"));
    assert!(parse.errors().is_empty());
    let items: Vec<Item> = parse.tree().items().collect();
    // my_wide_car: vehicle, then seven keep constraints (§8.7.2.2 Code 1).
    assert_eq!(items.len(), 8);
    let Item::Param(field) = &items[0] else {
        panic!("{:?}", items[0])
    };
    assert_eq!(
        field.names().map(|n| n.text()).collect::<Vec<_>>(),
        ["my_wide_car"]
    );
    let Some(Type::Named(ty)) = field.ty() else {
        panic!()
    };
    assert_eq!(ty.name().unwrap().text(), "vehicle");

    // keep(my_wide_car.bounding_box.width >= 1.95m)
    let Item::Keep(keep) = &items[2] else {
        panic!()
    };
    assert_eq!(keep.qualifier(), None);
    let Some(Expr::Bin(bin)) = keep.expr() else {
        panic!()
    };
    assert_eq!(bin.op(), Some(BinaryOp::Ge));
    let Some(Expr::Field(width)) = bin.lhs() else {
        panic!()
    };
    assert_eq!(width.field().unwrap().text(), "width");
    let Some(Expr::Field(bbox)) = width.receiver() else {
        panic!()
    };
    assert_eq!(bbox.field().unwrap().text(), "bounding_box");
    let Some(Expr::Literal(lit)) = bin.rhs() else {
        panic!()
    };
    assert_eq!(
        lit.value(),
        Ok(LiteralValue::Physical(Number::Float(1.95), "m".to_string()))
    );

    // keep(my_wide_car.axles.size() == 2)
    let Item::Keep(keep) = &items[4] else {
        panic!()
    };
    let Some(Expr::Bin(bin)) = keep.expr() else {
        panic!()
    };
    let Some(Expr::Call(call)) = bin.lhs() else {
        panic!()
    };
    assert_eq!(call.name().unwrap().text(), "size");
    assert_eq!(call.args().unwrap().args().count(), 0);
    let Some(Expr::Literal(two)) = bin.rhs() else {
        panic!()
    };
    assert_eq!(two.value(), Ok(LiteralValue::Number(Number::UInt(2))));

    // keep(my_wide_car.axles[1].number_of_wheels == 2): the index is 1.
    let Item::Keep(keep) = &items[6] else {
        panic!()
    };
    let Some(Expr::Bin(bin)) = keep.expr() else {
        panic!()
    };
    let Some(Expr::Field(wheels)) = bin.lhs() else {
        panic!()
    };
    let Some(Expr::Index(index)) = wheels.receiver() else {
        panic!()
    };
    let Some(Expr::Literal(one)) = index.index() else {
        panic!()
    };
    assert_eq!(one.value(), Ok(LiteralValue::Number(Number::UInt(1))));
}

#[test]
fn prevent_collision_behavior_reads_through_the_ast() {
    let parse = parse(&seed("seed_prevent_collision"));
    assert!(parse.errors().is_empty());
    let Some(Item::Scenario(scenario)) = parse.tree().items().next() else {
        panic!()
    };
    assert_eq!(
        scenario.name().unwrap().name().unwrap().text(),
        "prevent_collision"
    );
    let members: Vec<Member> = scenario.members().collect();
    assert_eq!(members.len(), 4);
    // var collision_time: time = sample(ego.time_to_collision(reference: other_car), every(2s))
    let Member::Var(var) = &members[2] else {
        panic!()
    };
    let sample = var.sample().unwrap();
    let Some(Expr::Call(ttc)) = sample.expr() else {
        panic!()
    };
    assert_eq!(ttc.name().unwrap().text(), "time_to_collision");
    let Some(Argument::Named(arg)) = ttc.args().unwrap().args().next() else {
        panic!()
    };
    assert_eq!(arg.name().unwrap().text(), "reference");
    let Some(EventCondition::Every(every)) = sample.event().unwrap().condition() else {
        panic!()
    };
    let Some(Expr::Literal(period)) = every.period() else {
        panic!()
    };
    assert_eq!(
        period.value(),
        Ok(LiteralValue::Physical(Number::UInt(2), "s".to_string()))
    );

    // do parallel: two invocations, the second with until rise(collision_time < 10s).
    let Member::Do(do_directive) = &members[3] else {
        panic!()
    };
    let Some(Member::Composition(parallel)) = do_directive.member() else {
        panic!()
    };
    assert_eq!(parallel.operator(), Some(CompositionOperator::Parallel));
    let invocations: Vec<Member> = parallel.members().collect();
    let Member::Invocation(ego_drive) = &invocations[1] else {
        panic!()
    };
    let call = ego_drive.call().unwrap();
    assert_eq!(call.name().unwrap().text(), "drive");
    let Some(Expr::Name(receiver)) = call.receiver() else {
        panic!()
    };
    assert_eq!(receiver.name().unwrap().text(), "ego");
    let with: Vec<Member> = ego_drive.with().unwrap().members().collect();
    assert!(
        matches!(&with[0], Member::ModifierApplication(m) if m.call().unwrap().name().unwrap().text() == "position")
    );
    let Member::Until(until) = &with[1] else {
        panic!()
    };
    assert!(matches!(
        until.event().unwrap().condition(),
        Some(EventCondition::Rise(_))
    ));
}

#[test]
fn declarations_read_through_the_ast() {
    let source = "\
import osc.standard
unit kph of speed is SI(m: 1, s: -1, factor: 0.277777778)
enum color: [red, green = 2]
struct |my struct| inherits base(kind == kind_enum!special):
    keep(default x == 1)
    def f(a: int = 3) -> float is only external lib.f(a)
";
    let parse = parse(source);
    assert!(parse.errors().is_empty(), "{:?}", parse.errors());
    let items: Vec<Item> = parse.tree().items().collect();
    let Item::Import(import) = &items[0] else {
        panic!()
    };
    assert_eq!(import.reference().as_deref(), Some("osc.standard"));
    assert!(!import.is_path());

    let Item::Unit(unit) = &items[1] else {
        panic!()
    };
    assert_eq!(unit.name().unwrap().text(), "kph");
    assert_eq!(unit.physical_type().unwrap().text(), "speed");
    let args: Vec<(String, Option<LiteralValue>)> = unit
        .si()
        .unwrap()
        .args()
        .map(|a| {
            let value = match a.value() {
                Some(Expr::Literal(l)) => l.value().ok(),
                _ => None,
            };
            (a.name().unwrap(), value)
        })
        .collect();
    assert_eq!(
        args,
        [
            ("m".to_string(), Some(LiteralValue::Number(Number::UInt(1)))),
            ("s".to_string(), Some(LiteralValue::Number(Number::Int(-1)))),
            (
                "factor".to_string(),
                Some(LiteralValue::Number(Number::Float(0.277777778)))
            ),
        ]
    );

    let Item::Enum(color) = &items[2] else {
        panic!()
    };
    let members: Vec<String> = color.members().map(|m| m.name().unwrap().text()).collect();
    assert_eq!(members, ["red", "green"]);

    let Item::Struct(st) = &items[3] else {
        panic!()
    };
    assert_eq!(st.name().unwrap().text(), "my struct");
    let condition = st.inherits().unwrap().condition().unwrap();
    assert_eq!(condition.field().unwrap().text(), "kind");
    let Some(Expr::EnumValue(value)) = condition.value() else {
        panic!()
    };
    assert_eq!(
        (
            value.enum_name().unwrap().text(),
            value.member().unwrap().text()
        ),
        ("kind_enum".to_string(), "special".to_string())
    );
    let members: Vec<Member> = st.members().collect();
    let Member::Keep(keep) = &members[0] else {
        panic!()
    };
    assert_eq!(keep.qualifier(), Some(ConstraintQualifier::Default));
    let Member::Method(method) = &members[1] else {
        panic!()
    };
    let body = method.body().unwrap();
    assert!(body.is_only());
    let Some(MethodImpl::External(call)) = body.implementation() else {
        panic!()
    };
    assert_eq!(call.syntax().to_string(), "lib.f(a)");
    let param = method.params().unwrap().params().next().unwrap();
    assert_eq!(param.name().unwrap().text(), "a");
    assert!(matches!(param.ty(), Some(Type::Primitive(p)) if p.kind() == Some(SyntaxKind::INT_KW)));
}

/// The tree's spans: the text of a node is its slice of the input.
#[test]
fn spans_are_byte_ranges_of_the_input() {
    let source = "struct s:\n    keep(a.b >= 1.5m)\n";
    let parse = parse(source);
    let keep = parse
        .syntax()
        .descendants()
        .find(|n| n.kind() == SyntaxKind::KEEP_CONSTRAINT)
        .unwrap();
    let range = keep.text_range();
    // "struct s:\n    " is 14 bytes; "keep(a.b >= 1.5m)" is 17.
    assert_eq!((u32::from(range.start()), u32::from(range.end())), (14, 31));
    assert_eq!(&source[14..31], keep.to_string());
}

/// The miette report names the file, line and column, shows the line and labels the span.
#[test]
fn diagnostics_render_with_a_snippet() {
    let source = "struct s:\n    x: = 1\n";
    let parse = parse(source);
    let error = &parse.errors()[0];
    let report = error.to_report("s.osc", source);
    let mut rendered = String::new();
    miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
        .render_report(&mut rendered, report.as_ref())
        .unwrap();
    assert!(
        rendered.contains("expected a type, found `=`"),
        "{rendered}"
    );
    assert!(rendered.contains("[s.osc:2:8]"), "{rendered}");
    assert!(rendered.contains("2 │     x: = 1"), "{rendered}");
    assert!(rendered.contains("expected a type"), "{rendered}");
    let index = dsl::syntax::LineIndex::new(source);
    assert_eq!(
        error.display("s.osc", &index).to_string(),
        "expected a type, found `=` at s.osc:2:8"
    );
}
