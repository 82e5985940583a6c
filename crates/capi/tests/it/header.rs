//! `include/oscsim.h` is what cbindgen generates from the crate now (cbindgen.toml): a change
//! of the API that is not in the committed header fails here. Regenerate with
//! `OSCSIM_BLESS_HEADER=1 cargo test -p oscsim-capi --test it header`.

use std::path::Path;

#[test]
fn header_is_up_to_date() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config =
        cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).expect("cbindgen.toml parses");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen reads the crate")
        .write(&mut generated);
    let generated = String::from_utf8(generated).expect("cbindgen writes UTF-8");
    let path = crate_dir.join("include").join("oscsim.h");
    if std::env::var_os("OSCSIM_BLESS_HEADER").is_some() {
        std::fs::write(&path, &generated).expect("include/oscsim.h is writable");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/oscsim.h differs from what cbindgen generates; regenerate it with \
         OSCSIM_BLESS_HEADER=1 cargo test -p oscsim-capi --test it header"
    );
}
