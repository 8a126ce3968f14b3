fn main() -> std::process::ExitCode {
    // The command runs on a thread with a deep stack, so that the simulations it runs allow
    // ordinary recursion (`vams::kernel::DEEP_CALL_DEPTH` nested calls).
    let deep = std::thread::Builder::new()
        .name("vams".into())
        .stack_size(vams::kernel::DEEP_STACK)
        .spawn(|| {
            vams::kernel::set_call_depth_limit(vams::kernel::DEEP_CALL_DEPTH);
            vams::cli::run()
        });
    match deep.map(std::thread::JoinHandle::join) {
        Ok(Ok(code)) => code,
        // A panic was reported by the hook already.
        Ok(Err(_)) => std::process::ExitCode::from(101),
        // No thread (a machine without the address space): the command runs here, with the
        // library's default depth.
        Err(_) => vams::cli::run(),
    }
}
