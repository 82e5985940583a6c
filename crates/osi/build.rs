//! Compiles the OSI 3.8.0 message definitions in `proto/` with the pure-Rust `protox`
//! compiler (no `protoc` needed), generates the Rust types with `prost-build`, and writes
//! the compiled `FileDescriptorSet` (with imports, without source info, as
//! `protoc --include_imports --descriptor_set_out` would) for the MCAP channel schema.

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out_dir = PathBuf::from(std::env::var("OUT_DIR")?);
    println!("cargo:rerun-if-changed=proto");

    let mut compiler = protox::Compiler::new(["proto"])?;
    compiler.include_imports(true);
    compiler.open_file("osi_groundtruth.proto")?;

    compiler.include_source_info(false);
    std::fs::write(
        out_dir.join("osi3_descriptor_set.bin"),
        compiler.encode_file_descriptor_set(),
    )?;

    compiler.include_source_info(true);
    prost_build::Config::new()
        .out_dir(&out_dir)
        .compile_fds(compiler.file_descriptor_set())?;
    Ok(())
}
