//! Generates the parser from the grammar at the top of the repository (`grammar/vhdl.lalrpop`).
use std::env;

fn main() {
    println!("cargo:rerun-if-changed=../../grammar");
    let out = env::var("OUT_DIR").expect("cargo sets OUT_DIR for build scripts");
    lalrpop::Configuration::new()
        .set_in_dir("../../grammar")
        .set_out_dir(&out)
        .emit_rerun_directives(true)
        .process()
        .expect("the grammar in grammar/ must compile");
}
