//! Prints the syntax tree dump and the syntax errors of an .osc file.
fn main() {
    let path = std::env::args().nth(1).expect("usage: parse_dump FILE.osc");
    let source = std::fs::read_to_string(&path).expect("readable file");
    let parse = dsl::syntax::parse(&source);
    print!("{}", dsl::syntax::debug_dump(&parse.syntax()));
    let index = dsl::syntax::LineIndex::new(&source);
    for e in parse.errors() {
        println!("{}", e.display(&path, &index));
    }
}
