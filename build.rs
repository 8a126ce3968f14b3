//! Generates the parser from `grammar/vhdl.lalrpop`, and the table of the bundled `stdlib/`
//! sources (so the binary carries its standard packages wherever it runs).
use std::{env, fs, path::Path};

fn main() {
    println!("cargo:rerun-if-changed=grammar");
    println!("cargo:rerun-if-changed=stdlib");
    let out = env::var("OUT_DIR").expect("cargo sets OUT_DIR for build scripts");
    lalrpop::Configuration::new()
        .set_in_dir("grammar")
        .set_out_dir(&out)
        .emit_rerun_directives(true)
        .process()
        .expect("the grammar in grammar/ must compile");

    let root = Path::new(&env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("stdlib");
    let mut entries = Vec::new();
    for lib in ["std", "ieee", "vams"] {
        let dir = root.join(lib);
        let mut files: Vec<_> = fs::read_dir(&dir)
            .expect("stdlib/<library> exists")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "vhd"))
            .collect();
        files.sort();
        for f in files {
            println!("cargo:rerun-if-changed={}", f.display());
            entries.push(format!(
                "    ({lib:?}, {:?}, include_str!({:?})),\n",
                format!(
                    "stdlib/{lib}/{}",
                    f.file_name().and_then(|n| n.to_str()).unwrap_or("")
                ),
                f.display().to_string()
            ));
        }
    }
    let table = format!(
        "/// (library, path, text) of every bundled standard source file.\npub const FILES: &[(&str, &str, &str)] = &[\n{}];\n",
        entries.concat()
    );
    fs::write(Path::new(&out).join("stdlib_files.rs"), table).expect("OUT_DIR is writable");
}
