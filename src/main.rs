fn main() {
    println!("vams");
}
