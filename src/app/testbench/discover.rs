//! Finding testbenches: entities of library `work` without ports whose name starts with
//! `tb_` or `test_`, sorted by name (a name declared twice counts once: the last one analysed,
//! as elaboration sees it).

use crate::ast::LibraryUnit;
use crate::source::FileId;

use super::super::load::Loaded;

/// One testbench found in the sources.
#[derive(Clone, Debug, PartialEq)]
pub struct Testbench {
    /// Entity name (lower case).
    pub name: String,
    /// The file that declares it.
    pub file: FileId,
}

/// True for the names `vams test` runs.
pub fn is_testbench_name(name: &str) -> bool {
    name.starts_with("tb_") || name.starts_with("test_")
}

/// The testbenches of `loaded` whose name contains `filter` (all when `None`).
pub fn discover(loaded: &Loaded, filter: Option<&str>) -> Vec<Testbench> {
    let filter = filter.map(str::to_ascii_lowercase);
    let mut found: Vec<Testbench> = Vec::new();
    for (id, ast) in &loaded.files {
        if loaded.sources.file(*id).library != "work" {
            continue;
        }
        for unit in &ast.units {
            let LibraryUnit::Entity(entity) = &unit.unit else {
                continue;
            };
            let name = entity.name.name.to_ascii_lowercase();
            if !entity.ports.is_empty()
                || !is_testbench_name(&name)
                || filter.as_deref().is_some_and(|f| !name.contains(f))
            {
                continue;
            }
            found.retain(|t| t.name != name);
            found.push(Testbench { name, file: *id });
        }
    }
    found.sort_by(|a, b| a.name.cmp(&b.name));
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::load::load;

    #[test]
    fn portless_entities_named_tb_or_test_in_name_order() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("benches.vhd"),
            r#"
entity tb_zeta is end entity;
entity test_alpha is generic (n : integer := 1); end entity;
entity tb_with_ports is port (signal a : in bit); end entity;
entity helper is end entity;
entity TB_Upper is end entity;
"#,
        )
        .unwrap();
        std::fs::write(dir.path().join("more.vhd"), "entity tb_beta is end;\n").unwrap();
        let loaded = load(&[dir.path().to_path_buf()]).unwrap();
        assert!(
            loaded.syntax_errors.is_empty(),
            "{:?}",
            loaded.syntax_errors
        );
        let names: Vec<String> = discover(&loaded, None)
            .into_iter()
            .map(|t| t.name)
            .collect();
        assert_eq!(names, ["tb_beta", "tb_upper", "tb_zeta", "test_alpha"]);
        let filtered: Vec<String> = discover(&loaded, Some("ETA"))
            .into_iter()
            .map(|t| t.name)
            .collect();
        assert_eq!(filtered, ["tb_beta", "tb_zeta"]);
        let beta = discover(&loaded, Some("beta")).remove(0);
        assert!(loaded.sources.file(beta.file).name.ends_with("more.vhd"));
    }

    #[test]
    fn the_stdlib_holds_no_testbench() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("e.vhd"), "entity e is end;").unwrap();
        let loaded = load(&[dir.path().to_path_buf()]).unwrap();
        assert!(discover(&loaded, None).is_empty());
    }
}
