fn main() -> std::process::ExitCode {
    vams::cli::run()
}
