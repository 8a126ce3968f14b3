//! The bundled functions whose meaning the kernel knows (`design::Intrinsic`): recognised
//! by where they are declared, the bundled file of their package as `vams` ships it, so that
//! a user's own `rising_edge` (or a package of that name in another library) is called as
//! written. Takes a subprogram being instantiated; gives the intrinsic it is, if any; never
//! changes what the instance's code does (the kernel's shortcut must agree with it).

use vams_design::{Intrinsic, SignalId};
use vams_semantics::stdlib;
use vams_syntax::source::SourceMap;

use crate::names::scope::Subprogram;

/// What an instance of `sub` bound to the actual signals `signals` computes, when it is the
/// `rising_edge` or `falling_edge` of the bundled `ieee.std_logic_1164` or `ieee.numeric_bit`.
pub(crate) fn of(sub: &Subprogram, signals: &[SignalId], sources: &SourceMap) -> Option<Intrinsic> {
    let rising = match sub.name.as_str() {
        "rising_edge" => true,
        "falling_edge" => false,
        _ => return None,
    };
    let ([param], [signal]) = (sub.params.as_slice(), signals) else {
        return None;
    };
    if !param.is_signal || sub.ret.is_none() {
        return None;
    }
    let file = sources.file(sub.span.file);
    let bundled = |package: &str| {
        file.library == "ieee"
            && stdlib::package_file("ieee", package)
                .is_some_and(|i| stdlib::FILES[i].2 == file.text.as_str())
    };
    let signal = *signal;
    if bundled("std_logic_1164") {
        Some(Intrinsic::StdLogicEdge { signal, rising })
    } else if bundled("numeric_bit") {
        Some(Intrinsic::BitEdge { signal, rising })
    } else {
        None
    }
}
