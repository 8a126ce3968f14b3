//! Access types (`new`, `.all`, `null`, `deallocate`), file types and file objects, and the
//! calls of the native procedures that work on them (`std.textio`, `file_open`, ...): the
//! declarations, the implicit operations each type brings (LRM 3.3.2, 3.4.1), and the
//! lowering of a call to [`Instr::Native`].

use std::cell::RefCell;
use std::rc::Rc;

use vams_design::{
    self as design, FileMode, FileObject, Instr, NativeProc, ParamMode, Value, VarId,
};
use vams_syntax::ast::{self, Actual};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::expressions::expr::Typed;
use crate::names::scope::{IoNative, Item, Native, Param, Part, Scope, Subprogram};
use crate::names::types::{AccessTy, FileTy, Sub, Ty};
use crate::{Elab, R};

impl<'a> Elab<'a> {
    /// `type p is access t;` and its implicit `deallocate`.
    pub(crate) fn access_type(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        designated: &ast::SubtypeIndication,
    ) -> R<()> {
        let access = Rc::new(AccessTy {
            name: name.name.clone(),
            designated: RefCell::new(None),
        });
        match self.incomplete_named(&designated.type_mark) {
            Some(k) => self.pending.incomplete[k].2.push(access.clone()),
            None => {
                let sub = self.subtype_indication(sc, designated)?;
                *access.designated.borrow_mut() = Some(sub.ty.clone());
            }
        }
        let ty = Ty::Access(access);
        self.declare(
            sc,
            name,
            Item::Type(Rc::new(Sub::of(ty.clone(), &name.name))),
        )?;
        let p = implicit_param("p", &ty, ParamMode::InOut, name.span);
        self.implicit(sc, "deallocate", vec![p], IoNative::Deallocate, name.span);
        Ok(())
    }

    /// The incomplete type (`type node;`) a type mark names, by its position in
    /// `self.pending.incomplete`.
    fn incomplete_named(&self, mark: &ast::Expr) -> Option<usize> {
        let ast::ExprKind::Name(id) = &mark.kind else {
            return None;
        };
        let decl = self.analysed.names.get(&id.span);
        self.pending
            .incomplete
            .iter()
            .rposition(|(n, span, _)| Some(span) == decl || *n == id.name)
    }

    /// After the full declaration of type `name`: the access types that designate its
    /// incomplete declaration designate it.
    pub(crate) fn complete(&mut self, sc: &mut Scope<'a>, name: &ast::Ident) {
        let Some(k) = self
            .pending
            .incomplete
            .iter()
            .rposition(|(n, ..)| *n == name.name)
        else {
            return;
        };
        let (_, incomplete, waiting) = self.pending.incomplete.remove(k);
        let Some(Item::Type(sub)) = sc.declared(name.span).cloned() else {
            return;
        };
        let full = sub.ty.clone();
        let item = Item::Type(sub);
        sc.declared_also_at(incomplete, item);
        for a in waiting {
            *a.designated.borrow_mut() = Some(full.clone());
            self.pending.completed_access.push(a);
        }
    }

    /// `type f is file of t;` and its implicit `file_open`, `file_close`, `read`, `write` and
    /// `endfile`.
    pub(crate) fn file_type(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        mark: &ast::Expr,
    ) -> R<()> {
        let element = self.type_mark(sc, mark)?.ty.clone();
        let ty = Ty::File(Rc::new(FileTy {
            name: name.name.clone(),
            element: element.clone(),
        }));
        self.declare(
            sc,
            name,
            Item::Type(Rc::new(Sub::of(ty.clone(), &name.name))),
        )?;
        let at = name.span;
        let string = self.standard_type("string").unwrap_or(Ty::Integer);
        let kind = self.standard_type("file_open_kind").unwrap_or(Ty::Integer);
        let status = self
            .standard_type("file_open_status")
            .unwrap_or(Ty::Integer);
        let f = || implicit_param("f", &ty, ParamMode::In, at);
        let mut open_kind = implicit_param("open_kind", &kind, ParamMode::In, at);
        open_kind.has_default = true;
        let open = vec![
            f(),
            implicit_param("external_name", &string, ParamMode::In, at),
            open_kind,
        ];
        self.implicit(sc, "file_open", open.clone(), IoNative::FileOpen, at);
        let mut with_status = vec![implicit_param("status", &status, ParamMode::Out, at)];
        with_status.extend(open);
        self.implicit(sc, "file_open", with_status, IoNative::FileOpen, at);
        self.implicit(sc, "file_close", vec![f()], IoNative::FileClose, at);
        let value = |mode| implicit_param("value", &element, mode, at);
        let read = vec![f(), value(ParamMode::Out)];
        self.implicit(sc, "read", read, IoNative::Read, at);
        let length = implicit_param("length", &Ty::Integer, ParamMode::Out, at);
        let read = vec![f(), value(ParamMode::Out), length];
        self.implicit(sc, "read", read, IoNative::Read, at);
        self.implicit(
            sc,
            "write",
            vec![f(), value(ParamMode::In)],
            IoNative::Write,
            at,
        );
        let endfile = Subprogram {
            name: "endfile".into(),
            params: vec![f()],
            ret: Some(Ty::Boolean),
            native: Some(Native::Io(IoNative::EndFile)),
            span: at,
            body: RefCell::new(None),
            instances: RefCell::new(Vec::new()),
        };
        sc.declare("endfile", Item::Subprogram(Rc::new(endfile)));
        Ok(())
    }

    /// Declares an implicit procedure of a type.
    fn implicit(
        &mut self,
        sc: &mut Scope<'a>,
        name: &str,
        params: Vec<Param<'a>>,
        op: IoNative,
        span: Span,
    ) {
        let sub = Subprogram {
            name: name.into(),
            params,
            ret: None,
            native: Some(Native::Io(op)),
            span,
            body: RefCell::new(None),
            instances: RefCell::new(Vec::new()),
        };
        sc.declare(name, Item::Subprogram(Rc::new(sub)));
    }

    /// `file f : t [open kind] is "name";`: a file object of the design, opened at the start
    /// of the run when the declaration names its file.
    pub(crate) fn file_decl(
        &mut self,
        sc: &mut Scope<'a>,
        names: &[ast::Ident],
        subtype: &ast::SubtypeIndication,
        open_kind: Option<&ast::Expr>,
        logical_name: Option<&ast::Expr>,
    ) -> R<()> {
        let sub = self.subtype_indication(sc, subtype)?;
        if !matches!(sub.ty, Ty::File(_)) {
            return Err(self.error(ElabError::TypeMismatch {
                span: subtype.span,
                expected: "a file type".into(),
                found: sub.ty.to_string(),
                help: Some(
                    "declare one: `type t is file of integer;` (or use std.textio's `text`)".into(),
                ),
            }));
        }
        let open = match logical_name {
            None => None,
            Some(n) => {
                let string = self.standard_type("string").unwrap_or(Ty::Integer);
                let Value::String(file) = self.static_value(sc, n, &string, "a file name")? else {
                    return Err(crate::Reported);
                };
                let mode = self.open_mode(sc, open_kind)?;
                Some((file, mode))
            }
        };
        for n in names {
            self.file_object(sc, n, &sub.ty, open.clone())?;
        }
        Ok(())
    }

    /// The `file_open_kind` of a file declaration as a mode (`read_mode` without one).
    fn open_mode(&mut self, sc: &Scope<'a>, open_kind: Option<&ast::Expr>) -> R<FileMode> {
        let Some(k) = open_kind else {
            return Ok(FileMode::Read);
        };
        let kind = self.standard_type("file_open_kind").unwrap_or(Ty::Integer);
        Ok(match self.static_value(sc, k, &kind, "a file_open_kind")? {
            Value::Enum(p) => FileMode::from_position(p).unwrap_or(FileMode::Read),
            _ => FileMode::Read,
        })
    }

    /// A file object of the design named `n`, declared as the constant `Value::File` it is.
    fn file_object(
        &mut self,
        sc: &mut Scope<'a>,
        n: &ast::Ident,
        ty: &Ty,
        open: Option<(String, FileMode)>,
    ) -> R<u32> {
        let id = self.design.files.len() as u32;
        self.design.files.push(FileObject {
            name: n.name.clone(),
            span: n.span,
            open,
        });
        let item = Item::Constant {
            value: Value::File(id),
            ty: ty.clone(),
        };
        self.declare(sc, n, item)?;
        Ok(id)
    }

    /// A file declaration in a process or subprogram whose file name is not static (a
    /// parameter): the file object, opened by an instruction where the declaration is
    /// elaborated at run time. `None` when the name is static (the design opens it at the
    /// start, [`Elab::file_decl`]).
    pub(crate) fn dynamic_file_decl(
        &mut self,
        sc: &mut Scope<'a>,
        p: &mut crate::sequential::process::Proc,
        names: &[ast::Ident],
        subtype: &ast::SubtypeIndication,
        open_kind: Option<&ast::Expr>,
        name: &ast::Expr,
    ) -> Option<R<()>> {
        let string = self.standard_type("string").unwrap_or(Ty::Integer);
        let quiet = self.errors.len();
        let logical = match self.expr_of(sc, name, &string) {
            Ok(t) if !matches!(t.e, design::Expr::Const(_)) => t.e,
            Ok(_) => return None,
            Err(_) => {
                // Reported again, once, by the static path.
                self.errors.truncate(quiet);
                return None;
            }
        };
        Some((|| {
            let sub = self.subtype_indication(sc, subtype)?;
            if !matches!(sub.ty, Ty::File(_)) {
                return self.file_decl(sc, names, subtype, open_kind, Some(name));
            }
            let kind = Value::Enum(self.open_mode(sc, open_kind)? as u32);
            for n in names {
                let id = self.file_object(sc, n, &sub.ty, None)?;
                p.emit(Instr::Native {
                    op: NativeProc::FileDeclare,
                    args: vec![
                        design::Expr::Const(Value::File(id)),
                        logical.clone(),
                        design::Expr::Const(kind.clone()),
                    ],
                    copy_back: Vec::new(),
                    span: n.span,
                });
            }
            Ok(())
        })())
    }

    /// `new t` or `new t'(value)` of the access type `want`.
    pub(crate) fn allocator(
        &mut self,
        sc: &Scope<'a>,
        inner: &ast::Expr,
        want: Option<&Ty>,
        span: Span,
    ) -> R<Typed> {
        let value = match &inner.kind {
            ast::ExprKind::Qualified(..) => self.expr(sc, inner, None)?,
            _ => {
                let si = ast::SubtypeIndication {
                    resolution: None,
                    type_mark: inner.clone(),
                    range: None,
                    tolerance: None,
                    span: inner.span,
                };
                // `new store_array(0 to size - 1)`: legal, but the object's bounds would be
                // known only at run time.
                let Some(sub) = self.where_static(|me| me.subtype_indication(sc, &si))? else {
                    return Err(self.error(ElabError::unsupported(
                        inner.span,
                        "an allocator of an array whose bounds are known only at run time",
                        "give the allocated array bounds known before the run (constants or generics)",
                    )));
                };
                Typed::new(
                    design::Expr::Const(crate::declarations::decls::default_value(&sub)),
                    sub.ty.clone(),
                )
            }
        };
        let Some(Ty::Access(a)) = want else {
            return Err(self.error(ElabError::invalid(
                span,
                "the type of this allocator is not known here",
                Some("assign it to an access variable, or qualify it: `ptr'(new t)`".into()),
            )));
        };
        if let Some(d) = a.designated()
            && !d.same(&value.ty)
        {
            return Err(self.error(ElabError::TypeMismatch {
                span,
                expected: format!("a new {d}"),
                found: value.ty.to_string(),
                help: None,
            }));
        }
        Ok(Typed::new(
            design::Expr::New(Box::new(value.e)),
            Ty::Access(a.clone()),
        ))
    }

    /// `p.all`, and what `p.f` and `p(i)` implicitly dereference: the designated object.
    pub(crate) fn deref(&mut self, p: Typed, span: Span) -> R<Typed> {
        let Ty::Access(a) = &p.ty else {
            return Ok(p);
        };
        let Some(ty) = a.designated() else {
            return Err(self.error(ElabError::invalid(
                span,
                format!("the type that `{}` designates is incomplete here", a.name),
                Some("complete the type declaration before this use".into()),
            )));
        };
        Ok(Typed::new(design::Expr::Deref(Box::new(p.e)), ty))
    }

    /// Whether an assignment target may reach into the heap: its root is a private variable
    /// of a protected type, or a variable whose type holds access values, or it names `.all`.
    /// Only then is it elaborated as an expression by [`Elab::heap_target`].
    pub(crate) fn may_reach_heap(&self, sc: &Scope<'a>, target: &ast::Expr) -> bool {
        fn holds_access(ty: &Ty) -> bool {
            match ty {
                Ty::Access(_) => true,
                Ty::Record(r) => r.fields.iter().any(|(_, t)| holds_access(t)),
                Ty::Array(a) => holds_access(&a.element),
                _ => false,
            }
        }
        let mut e = target;
        loop {
            match &e.kind {
                ast::ExprKind::Selected(_, s) if s.name == "all" => return true,
                ast::ExprKind::Selected(prefix, s)
                    if !self.analysed.names.contains_key(&s.span) =>
                {
                    e = prefix
                }
                ast::ExprKind::Apply(prefix, _) => e = prefix,
                ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) => {
                    return match self.resolved_item(sc, id) {
                        Some(Item::PrivateVariable { .. }) => true,
                        Some(Item::Variable { ty, .. }) => holds_access(&ty),
                        _ => false,
                    };
                }
                _ => return false,
            }
        }
    }

    /// An assignment target that reaches into the heap (`p.all`, `p.f`, `p(i)`,
    /// `r.next.value`): the access value whose object is updated, the path in that object,
    /// and the target's type. `None` for a target that does not dereference.
    pub(crate) fn heap_target(
        &mut self,
        sc: &Scope<'a>,
        target: &ast::Expr,
    ) -> R<Option<(design::Expr, Vec<Part>, Ty)>> {
        if let ast::ExprKind::Name(id) = &target.kind
            && let Some(Item::PrivateVariable {
                object,
                field,
                record,
                ty,
            }) = self.resolved_item(sc, id)
        {
            let part = Part::Element {
                index: design::Expr::Const(Value::Integer(field as i64)),
                container: record,
            };
            return Ok(Some((design::Expr::Const(object), vec![part], ty)));
        }
        let (prefix, select): (&ast::Expr, Option<&ast::Ident>) = match &target.kind {
            ast::ExprKind::Selected(prefix, suffix)
                if !self.analysed.names.contains_key(&suffix.span) =>
            {
                (prefix, Some(suffix))
            }
            ast::ExprKind::Apply(prefix, _) => (prefix, None),
            _ => return Ok(None),
        };
        // The object being selected from: through an access value, or itself in the heap.
        let base = self.expr(sc, prefix, None)?;
        let (pointer, mut path, ty) = match &base.ty {
            Ty::Access(_) => {
                let object = self.deref(base.clone(), prefix.span)?;
                (base.e, Vec::new(), object.ty)
            }
            _ => match self.heap_target(sc, prefix)? {
                Some(t) => t,
                None => return Ok(None),
            },
        };
        match (select, &target.kind) {
            (Some(s), _) if s.name == "all" => Ok(Some((pointer, path, ty))),
            (Some(s), _) => {
                let (pos, field) = self.record_field(&ty, s, target.span)?;
                path.push(Part::Element {
                    index: design::Expr::Const(Value::Integer(pos as i64)),
                    container: ty.to_design(),
                });
                Ok(Some((pointer, path, field)))
            }
            (None, ast::ExprKind::Apply(_, args)) => {
                let Ty::Array(arr) = &ty else {
                    return Err(self.error(ElabError::invalid(
                        target.span,
                        format!("a value of type {ty} cannot be indexed"),
                        None,
                    )));
                };
                let arr = arr.clone();
                let [
                    ast::Assoc {
                        actual: Actual::Expr(i),
                        formal: None,
                        ..
                    },
                ] = args.as_slice()
                else {
                    return Err(self.error(ElabError::unsupported(
                        target.span,
                        "this target in an object an access value designates",
                        "assign one element `p(i) := x`, a field `p.f := x` or the whole `p.all := x`",
                    )));
                };
                let index = self.index_position(sc, i, &arr.index)?;
                let container = ty.to_design();
                path.push(Part::Element { index, container });
                Ok(Some((pointer, path, arr.element.clone())))
            }
            _ => Ok(None),
        }
    }

    /// A call of a native I/O procedure (`write(l, x)`, `file_open(f, "a.txt")`, ...): the
    /// instruction and the variable parts written back after it.
    pub(crate) fn native_procedure_call(
        &mut self,
        sc: &Scope<'a>,
        vars: &[design::Variable],
        subs: Vec<Rc<Subprogram<'a>>>,
        call: &ast::Expr,
    ) -> R<(Instr, Vec<crate::sequential::process::PartActual>)> {
        let (args, name_span) = match &call.kind {
            ast::ExprKind::Apply(prefix, args) => (
                args.as_slice(),
                crate::expressions::expr::designator_span(prefix),
            ),
            _ => (&[][..], crate::expressions::expr::designator_span(call)),
        };
        // The two `file_open`s of a file type take three arguments each: the one with a
        // status starts with a variable that is not a file.
        let subs = match subs.as_slice() {
            [a, b] if a.name == "file_open" && args.len() == 3 => {
                let first_is_file = match &args[0].actual {
                    Actual::Expr(e) => matches!(self.expr(sc, e, None)?.ty, Ty::File(_)),
                    _ => true,
                };
                let with_status = |s: &Rc<Subprogram<'a>>| s.params.len() == 4;
                vec![
                    if with_status(a) != first_is_file {
                        a
                    } else {
                        b
                    }
                    .clone(),
                ]
            }
            _ => subs,
        };
        let (sub, slots) = self.resolve_call(subs, args, false, call.span, name_span)?;
        let Some(Native::Io(io)) = sub.native else {
            return Err(crate::Reported);
        };
        let mut values = Vec::with_capacity(sub.params.len());
        let mut copy_back = Vec::new();
        let mut parts = Vec::new();
        for (k, (p, actual)) in sub.params.iter().zip(&slots).enumerate() {
            if p.mode == ParamMode::In {
                let t = match (actual, p.default) {
                    (None, None) if p.has_default => {
                        // `file_open`'s `open_kind`.
                        Typed::new(design::Expr::Const(Value::Enum(0)), p.ty.clone())
                    }
                    _ => self.argument(sc, p, *actual, call.span)?,
                };
                values.push(t.e);
                continue;
            }
            let Some(actual) = actual else {
                return Err(self.error(ElabError::invalid(
                    call.span,
                    format!("the `out` parameter `{}` needs an actual variable", p.name),
                    None,
                )));
            };
            let (id, path, ty) = self.variable_target(sc, vars, actual)?;
            self.actual_of_type(actual, &ty, p)?;
            // Passed in even when `out`: a read of a string or bit vector takes the target's
            // length.
            let value = path
                .iter()
                .fold(design::Expr::Var(id), |e, part| part.of(e));
            values.push(value);
            if path.is_empty() {
                copy_back.push((k, id));
            } else {
                parts.push(crate::sequential::process::PartActual {
                    param: VarId(k as u32),
                    var: id,
                    path,
                    ty,
                });
            }
        }
        let op = self.native_proc(io, &sub, call.span)?;
        Ok((
            Instr::Native {
                op,
                args: values,
                copy_back,
                span: call.span,
            },
            parts,
        ))
    }

    /// What a native procedure does, from the overload chosen.
    fn native_proc(&mut self, io: IoNative, sub: &Subprogram<'a>, span: Span) -> R<NativeProc> {
        let value_ty = sub.params.get(1).map(|p| p.ty.to_design());
        let on_file = matches!(sub.params.first().map(|p| &p.ty), Some(Ty::File(_)));
        let good = sub.params.len() == 3;
        Ok(match (io, value_ty) {
            (IoNative::ReadLine, _) => NativeProc::ReadLine,
            (IoNative::WriteLine, _) => NativeProc::WriteLine,
            (IoNative::Read, Some(ty)) if on_file => NativeProc::FileRead { ty },
            (IoNative::Write, Some(ty)) if on_file => NativeProc::FileWrite { ty },
            (IoNative::Read, Some(ty)) => NativeProc::Read { ty, good },
            (IoNative::Write, Some(ty)) => NativeProc::Write { ty },
            (IoNative::HRead, Some(ty)) => NativeProc::ReadDigits { bits: 4, good, ty },
            (IoNative::ORead, Some(ty)) => NativeProc::ReadDigits { bits: 3, good, ty },
            (IoNative::HWrite, Some(ty)) => NativeProc::WriteDigits { bits: 4, ty },
            (IoNative::OWrite, Some(ty)) => NativeProc::WriteDigits { bits: 3, ty },
            (IoNative::FileOpen, _) => NativeProc::FileOpen {
                status: sub.params.len() == 4,
            },
            (IoNative::FileClose, _) => NativeProc::FileClose,
            (IoNative::Deallocate, _) => NativeProc::Deallocate,
            _ => {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("`{}` is a function", sub.name),
                    None,
                )));
            }
        })
    }
}

/// A parameter of an implicitly declared operation.
fn implicit_param<'a>(name: &str, ty: &Ty, mode: ParamMode, span: Span) -> Param<'a> {
    Param {
        name: name.into(),
        span,
        ty: ty.clone(),
        has_default: false,
        default: None,
        is_signal: false,
        mode,
    }
}
