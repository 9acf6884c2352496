use grainscope::physics::collision::*;
#[test]
fn probe() {
    let s = Setup::reference_ice();
    for v in [8.0, 4.0, 2.0, 1.5] {
        let c = collide(&s, v, &Options::default()).unwrap();
        println!(
            "v={v} {:?} e={:.4} tc={:.3e} tH={:.3e} crack={:.3} bulk={:.3} err={:.2e} {:?}",
            c.outcome,
            c.e_adhesive,
            c.contact_time,
            c.hertz_time,
            c.crack_fraction(),
            c.bulk_fraction(),
            c.energy_error,
            c.stats
        );
    }
    let mut q = s;
    q.t_vis = 1e-14;
    for tv in [1e-15, 1e-14, 1e-13, 1e-12, 1e-10, 1e-9, 1e-8] {
        q.t_vis = tv;
        let c = collide(&q, 4.0, &Options::default()).unwrap();
        println!(
            "tvis={tv:e} {:?} e={:.5} tc={:.3e} err={:.2e} {:?}",
            c.outcome, c.e_adhesive, c.contact_time, c.energy_error, c.stats
        );
    }
}
#[test]
fn steps() {
    let s = Setup::reference_ice();
    let c = collide(
        &s,
        8.0,
        &Options {
            record: true,
            ..Options::default()
        },
    )
    .unwrap();
    let _ = c;
}
#[test]
fn timing() {
    let s = Setup::reference_ice();
    for rtol in [1e-5, 1e-6, 1e-7, 1e-8] {
        let o = Options {
            rtol,
            ..Options::default()
        };
        let t0 = std::time::Instant::now();
        let mut e = 0.0;
        for _ in 0..200 {
            e = collide(&s, 8.0, &o).unwrap().e_adhesive;
        }
        println!(
            "rtol={rtol:e} e={e:.9} {:.1} us",
            t0.elapsed().as_secs_f64() / 200.0 * 1e6
        );
    }
}
