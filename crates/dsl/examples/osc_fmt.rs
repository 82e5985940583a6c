//! Prints an .osc file in canonical format (or its syntax errors).
fn main() {
    let path = std::env::args().nth(1).expect("usage: osc_fmt FILE.osc");
    let source = std::fs::read_to_string(&path).expect("readable file");
    match dsl::syntax::format(&source) {
        Ok(text) => print!("{text}"),
        Err(errors) => {
            let index = dsl::syntax::LineIndex::new(&source);
            for e in errors {
                eprintln!("{}", e.display(&path, &index));
            }
        }
    }
}
