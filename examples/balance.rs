use grainscope::preset::Preset;
use grainscope::scene::{self, Parts, Progress};
use std::time::Instant;
fn main() {
    let path = std::env::args().nth(1).unwrap();
    let n: usize = std::env::args().nth(2).map_or(2, |s| s.parse().unwrap());
    let preset = Preset::load(std::path::Path::new(&path)).unwrap();
    let params = preset.scene;
    let mut known = Vec::new();
    let mut total_max = 0.0;
    let mut total_sum = 0.0;
    for round in 1.. {
        let mut times = Vec::new();
        let mut made = Vec::new();
        let mut of = 1;
        let mut done = false;
        for part in 0..n {
            let p = Progress::default().with_parts(Parts { part, of: n, known: known.clone() });
            let t = Instant::now();
            let r = scene::compute(&params, &p);
            times.push(t.elapsed().as_secs_f64());
            match p.share() {
                None => {
                    done = true;
                    let _ = r;
                    break;
                }
                Some(s) => {
                    of = s.of;
                    made.extend(s.made);
                }
            }
            if part + 1 >= of {
                break;
            }
        }
        let mx = times.iter().cloned().fold(0.0, f64::max);
        let sm: f64 = times.iter().sum();
        total_max += mx;
        total_sum += sm;
        println!("round {round}: {:?} (of {of})", times.iter().map(|t| format!("{t:.2}")).collect::<Vec<_>>());
        if done {
            break;
        }
        known.extend(made);
    }
    println!("sum of max {total_max:.2} s, ideal {:.2} s", total_sum / n as f64);
}
