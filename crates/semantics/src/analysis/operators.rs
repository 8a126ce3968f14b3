//! The predefined operators: declared implicitly right after each type declaration (LRM
//! 1076-2002 7.2), and those of the universal types, declared in `std.standard`.

use vams_syntax::ast::ObjectClass;
use vams_syntax::source::Span;

use super::scope::{DeclKind, Param, Purity, RegionId, Signature};
use super::types::{TypeId, TypeKind, UNIVERSAL_INTEGER, UNIVERSAL_REAL};
use super::units::Analyzer;

const ARITHMETIC: [&str; 4] = ["+", "-", "*", "/"];
const ORDERING: [&str; 4] = ["<", "<=", ">", ">="];
const LOGICAL: [&str; 6] = ["and", "or", "nand", "nor", "xor", "xnor"];
const SHIFTS: [&str; 6] = ["sll", "srl", "sla", "sra", "rol", "ror"];

impl Analyzer<'_> {
    /// Declares the operators a new type `t` brings, in the current region.
    pub fn implicit_operators(&mut self, t: TypeId, span: Span) {
        // `boolean` and `bit` are the first two types of std.standard; their own operators
        // already need them.
        let in_standard = self.out.units[self.cur].library == "std"
            && self.out.units[self.cur].name == "standard";
        let logical_type = in_standard && matches!(self.types().name(t), "boolean" | "bit");
        if in_standard {
            match self.types().name(t) {
                "boolean" => self.std.boolean = t,
                "bit" => self.std.bit = t,
                "integer" => self.std.integer = t,
                "real" => self.std.real = t,
                _ => {}
            }
        }
        let boolean = self.std.boolean;
        let integer = self.std.integer;
        let real = self.std.real;
        let kind = self.types().kind(t).clone();
        let is_file = matches!(kind, TypeKind::File(_));
        if !is_file {
            for op in ["=", "/="] {
                self.operator(op, &[t, t], boolean, span);
            }
        }
        let logical_element = |a: &Analyzer, e: TypeId| e == a.std.boolean || e == a.std.bit;
        match kind {
            TypeKind::Integer | TypeKind::Real => {
                for op in ORDERING {
                    self.operator(op, &[t, t], boolean, span);
                }
                for op in ARITHMETIC {
                    self.operator(op, &[t, t], t, span);
                }
                if kind == TypeKind::Integer {
                    for op in ["mod", "rem"] {
                        self.operator(op, &[t, t], t, span);
                    }
                }
                self.operator("**", &[t, integer], t, span);
                for op in ["+", "-", "abs"] {
                    self.operator(op, &[t], t, span);
                }
            }
            TypeKind::Physical => {
                for op in ORDERING {
                    self.operator(op, &[t, t], boolean, span);
                }
                for op in ["+", "-"] {
                    self.operator(op, &[t, t], t, span);
                }
                for op in ["+", "-", "abs"] {
                    self.operator(op, &[t], t, span);
                }
                for scalar in [integer, real] {
                    self.operator("*", &[t, scalar], t, span);
                    self.operator("*", &[scalar, t], t, span);
                    self.operator("/", &[t, scalar], t, span);
                }
                self.operator("/", &[t, t], UNIVERSAL_INTEGER, span);
            }
            TypeKind::Enum { .. } => {
                for op in ORDERING {
                    self.operator(op, &[t, t], boolean, span);
                }
                if logical_type {
                    for op in LOGICAL {
                        self.operator(op, &[t, t], t, span);
                    }
                    self.operator("not", &[t], t, span);
                }
            }
            TypeKind::File(element) => self.file_operations(t, element, span),
            TypeKind::Access(_) => {
                let p = ("p", ObjectClass::Variable, t, false);
                self.subprogram_named("deallocate", &[p], None, span);
            }
            TypeKind::Array { indexes, element } if indexes.len() == 1 => {
                if self.types().is_discrete(element) {
                    for op in ORDERING {
                        self.operator(op, &[t, t], boolean, span);
                    }
                }
                for args in [[t, t], [t, element], [element, t], [element, element]] {
                    self.operator("&", &args, t, span);
                }
                if logical_element(self, element) {
                    for op in LOGICAL {
                        self.operator(op, &[t, t], t, span);
                    }
                    self.operator("not", &[t], t, span);
                    for op in SHIFTS {
                        self.operator(op, &[t, integer], t, span);
                    }
                }
            }
            _ => {}
        }
    }

    /// The arithmetic operators of universal_integer and universal_real (LRM 7.2.4, 7.2.6),
    /// declared first in `std.standard`: its own ranges (`-2147483648`) need them.
    pub fn universal_arithmetic(&mut self) {
        let span = Span::default();
        for u in [UNIVERSAL_INTEGER, UNIVERSAL_REAL] {
            for op in ARITHMETIC {
                self.operator(op, &[u, u], u, span);
            }
            for op in ["+", "-", "abs"] {
                self.operator(op, &[u], u, span);
            }
        }
        for op in ["mod", "rem"] {
            self.operator(
                op,
                &[UNIVERSAL_INTEGER, UNIVERSAL_INTEGER],
                UNIVERSAL_INTEGER,
                span,
            );
        }
        self.operator(
            "*",
            &[UNIVERSAL_REAL, UNIVERSAL_INTEGER],
            UNIVERSAL_REAL,
            span,
        );
        self.operator(
            "*",
            &[UNIVERSAL_INTEGER, UNIVERSAL_REAL],
            UNIVERSAL_REAL,
            span,
        );
        self.operator(
            "/",
            &[UNIVERSAL_REAL, UNIVERSAL_INTEGER],
            UNIVERSAL_REAL,
            span,
        );
    }

    /// The universal operators that name `boolean` and `integer`, declared at the end of
    /// `std.standard`.
    pub fn universal_relations(&mut self, region: RegionId) {
        let boolean = self.std.boolean;
        let integer = self.std.integer;
        let saved = std::mem::replace(&mut self.scope, vec![region]);
        let span = Span::default();
        for u in [UNIVERSAL_INTEGER, UNIVERSAL_REAL] {
            for op in ["=", "/="].into_iter().chain(ORDERING) {
                self.operator(op, &[u, u], boolean, span);
            }
            self.operator("**", &[u, integer], u, span);
        }
        self.scope = saved;
    }

    /// The implicit subprograms of a file type (LRM 3.4.1), with the LRM's formal names:
    /// `file_open`, `file_close`, `read`, `write`, `endfile`.
    fn file_operations(&mut self, f: TypeId, element: TypeId, span: Span) {
        use ObjectClass::{Constant, File, Variable};
        let std = self.std;
        let (string, kind, status) = (std.string, self.open_kind(), self.open_status());
        let open = [
            ("f", File, f, false),
            ("external_name", Constant, string, false),
            ("open_kind", Constant, kind, true),
        ];
        self.subprogram_named("file_open", &open, None, span);
        let mut with_status = vec![("status", Variable, status, false)];
        with_status.extend(open);
        self.subprogram_named("file_open", &with_status, None, span);
        self.subprogram_named("file_close", &[("f", File, f, false)], None, span);
        let (file, value) = (("f", File, f, false), ("value", Variable, element, false));
        self.subprogram_named("read", &[file, value], None, span);
        let length = ("length", Variable, std.integer, false);
        self.subprogram_named("read", &[file, value, length], None, span);
        let value = ("value", Constant, element, false);
        self.subprogram_named("write", &[file, value], None, span);
        self.subprogram_named("endfile", &[file], Some(std.boolean), span);
    }

    /// `std.standard`'s `file_open_kind` / `file_open_status` as visible here.
    fn open_kind(&self) -> TypeId {
        self.visible_type("file_open_kind")
    }

    fn open_status(&self) -> TypeId {
        self.visible_type("file_open_status")
    }

    fn visible_type(&self, name: &str) -> TypeId {
        match self.lookup(name).as_deref() {
            Some([d]) => match self.out.decl(*d).kind {
                DeclKind::Type(t) => t,
                _ => super::types::UNKNOWN,
            },
            _ => super::types::UNKNOWN,
        }
    }

    /// Declares an implicit subprogram in the current region; the first parameter of a
    /// default-less list is named `f`, the others `p1`, `p2`... (only their types matter).
    fn subprogram_named(
        &mut self,
        name: &str,
        params: &[(&str, ObjectClass, TypeId, bool)],
        result: Option<TypeId>,
        span: Span,
    ) {
        let params = params
            .iter()
            .map(|&(n, class, ty, has_default)| Param {
                name: n.to_string(),
                class,
                ty,
                has_default,
            })
            .collect();
        let d = self.push_decl(
            name,
            span,
            DeclKind::Subprogram(Signature {
                params,
                result,
                purity: Purity::Impure,
            }),
        );
        let region = *self.scope.last().expect("a unit always has a region");
        self.out.regions[region.0 as usize].add(name, d);
    }

    fn operator(&mut self, op: &str, args: &[TypeId], result: TypeId, span: Span) {
        let names = ["l", "r"];
        let params = args
            .iter()
            .zip(if args.len() == 1 {
                &names[1..]
            } else {
                &names[..]
            })
            .map(|(&ty, n)| Param {
                name: (*n).to_string(),
                class: ObjectClass::Constant,
                ty,
                has_default: false,
            })
            .collect();
        let sig = Signature {
            params,
            result: Some(result),
            purity: Purity::Predefined,
        };
        let name = format!("\"{op}\"");
        let d = self.push_decl(&name, span, DeclKind::Subprogram(sig));
        let region = *self.scope.last().expect("a unit always has a region");
        self.out.regions[region.0 as usize].add(&name, d);
    }
}
