//! A 100-equation RC ladder: residual and Jacobian against hand-computed values, and the cost
//! of one evaluation (printed; run with `--release --nocapture` for a meaningful figure).

use super::fixture::*;
use vams_design::NatureId;
use vams_solver::DaeSystem;

#[test]
fn rc_ladder_residual_and_jacobian_are_right_and_cheap() {
    // Source (3 unknowns), 19 sections of series R and shunt C (5 each), a load (2): 100.
    let mut b = Builder::new();
    let el = NatureId(0);
    let gnd = b.ground(el);
    let mut node = b.terminal("n0", el);
    let (vs, _) = b.branch("vs", "is", node, gnd);
    b.equation("vs == 1.0;", q(vs), c(1.0));
    let mut caps = Vec::new();
    for k in 1..=19 {
        let next = b.terminal(&format!("n{k}"), el);
        let (vr, ir) = b.branch(&format!("vr{k}"), &format!("ir{k}"), node, next);
        b.equation("vr == 1.0e3 * ir;", q(vr), mul(c(1e3), q(ir)));
        let (vc, ic) = b.branch(&format!("vc{k}"), &format!("ic{k}"), next, gnd);
        b.equation("ic == 1.0e-6 * vc'dot;", q(ic), mul(c(1e-6), dot(vc)));
        caps.push((vc, ic));
        node = next;
    }
    let (vl, il) = b.branch("vl", "il", node, gnd);
    b.equation("vl == 1.0e4 * il;", q(vl), mul(c(1e4), q(il)));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let n = sys.len();
    assert_eq!(n, 100);
    let x: Vec<f64> = (0..n).map(|i| 0.01 * i as f64).collect();
    let xdot: Vec<f64> = (0..n).map(|i| 0.5 - 0.003 * i as f64).collect();
    let mut out = vec![0.0; n];
    sys.residual(0.0, &x, &xdot, &mut out);
    // Solver row of an assembly row (rows are reordered so row j is matched to unknown j).
    let row_source = sys.row_source().to_vec();
    let solver_row = |r: usize| row_source.iter().position(|&s| s == r).unwrap();
    // The capacitor rows: ic - 1e-6 vc'dot.
    for (k, (vc, ic)) in caps.iter().enumerate() {
        let row = solver_row(2 + 2 * k);
        let (sv, si) = (
            sys.quantity_slot(*vc).expect("kept"),
            sys.quantity_slot(*ic).expect("kept"),
        );
        assert_eq!(out[row], x[si] - 1e-6 * xdot[sv]);
    }
    let mut jac = vec![0.0; sys.pattern().len()];
    sys.jacobian(0.0, &x, &xdot, 1e5, &mut jac);
    for (k, &(row, col)) in sys.pattern().iter().enumerate() {
        if let Some(p) = caps
            .iter()
            .position(|&(vc, _)| sys.quantity_slot(vc).expect("kept") == col)
            && row == solver_row(2 + 2 * p)
        {
            assert_eq!(jac[k], -1e-6 * 1e5);
        }
    }

    let runs = 20_000;
    let start = std::time::Instant::now();
    for _ in 0..runs {
        sys.residual(0.0, &x, &xdot, &mut out);
        sys.jacobian(0.0, &x, &xdot, 1e5, &mut jac);
    }
    let each = start.elapsed().as_secs_f64() / runs as f64;
    eprintln!(
        "{n} equations, {} Jacobian entries: residual + Jacobian in {:.2} us",
        jac.len(),
        each * 1e6
    );
}
