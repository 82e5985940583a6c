//! Bad input never panics or hangs the checker and the resolver: programs stitched from
//! fragments of declarations, constraints and behaviors (right and wrong), and arbitrary text.

use proptest::prelude::*;

const FRAGMENTS: &[&str] = &[
    "car: vehicle\n",
    "x: length\n",
    "n: uint = 3\n",
    "g: vehicle_group\n",
    "keep(x > 5m)\n",
    "keep(x < 2m)\n",
    "keep(x == 1m + 1s)\n",
    "keep(x in [1m..1e308m])\n",
    "keep(x == 1e308m * 1e308)\n",
    "keep(n == 18446744073709551615)\n",
    "keep(n < 0)\n",
    "keep(car.vehicle_category in [bus, truck])\n",
    "keep(car.axles.size() == 1000000)\n",
    "keep(car.axles[3].number_of_wheels == 2)\n",
    "keep(car.axles[-1].number_of_wheels == 2)\n",
    "keep(car.category == car)\n",
    "keep(g.vehicles.size() <= 3)\n",
    "for v in g.vehicles:\n    keep(v.category == bus)\n",
    "for v in car:\n    keep(v == 1)\n",
    "struct s inherits s\n",
    "actor a inherits b\nactor b inherits a\n",
    "struct t:\n    l: list of t\n    keep(l.size() == 2)\nz: t\n",
    "type q is SI(m: 200)\n",
    "unit qq of length is SI(m: 1, factor: 0)\n",
    "enum e: [a, b]\nextend e: [a]\n",
    "scenario sc:\n    v: vehicle\n    do v.drive() with:\n        speed(10m)\n",
    "scenario sc2:\n    do serial:\n        wait elapsed(1s)\n",
    "import \"nowhere.osc\"\n",
    "import osc.standard\n",
    "keep(it)\n",
    "keep(actor.speed > 1mps)\n",
    "modifier m of vehicle.drive\n",
    "keep((((((x))))) == (((1m))))\n",
    "keep(x / 0 == 1m)\n",
    "keep(0 * x == 1m)\n",
    ")(][:.\n",
    "    indented: int\n",
];

fn check(text: &str) {
    let no_files = |_: &std::path::Path| None;
    if let Ok(p) = dsl::check_source_with("fuzz.osc", text, &no_files) {
        let _ = p.resolve(7);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn stitched_programs_never_panic(picks in proptest::collection::vec(0..FRAGMENTS.len(), 0..8)) {
        let text: String = picks.iter().map(|i| FRAGMENTS[*i]).collect();
        check(&text);
    }

    #[test]
    fn arbitrary_text_never_panics(text in "[a-z_ :.()\\[\\]=<>+*/0-9\n\"!-]{0,200}") {
        check(&text);
    }
}
