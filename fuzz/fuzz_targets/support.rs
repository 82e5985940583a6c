//! Shared by the fuzz targets: deterministic numbers drawn from the input (so a crash input
//! replays exactly), and the hang watchdog.
#![allow(dead_code)] // Each target uses a part.

use std::hash::{DefaultHasher, Hash, Hasher};

/// A splitmix64 stream seeded by the input's hash.
pub struct Draws(u64);

impl Draws {
    /// Seeded by `data`.
    pub fn new(data: &[u8]) -> Self {
        let mut h = DefaultHasher::new();
        data.hash(&mut h);
        Draws(h.finish())
    }

    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [−1, 1).
    pub fn signed(&mut self) -> f64 {
        self.unit() * 2.0 - 1.0
    }

    /// A coin toss.
    pub fn bool(&mut self) -> bool {
        self.next() & 1 == 1
    }
}

/// Whether `text` has a 1-based line `line`, lines ending at `\n`, `\r\n` or a lone `\r` as
/// every reader counts them (XML 1.0 §2.11; `source::LineIndex`). Invalid UTF-8 is replaced
/// first, which never adds or removes a line end.
pub fn has_line(text: &[u8], line: u32) -> bool {
    let text = String::from_utf8_lossy(text);
    source::LineIndex::new(&text)
        .line_range(&text, line)
        .is_some()
}

/// Runs `f` with rayon's parallel work (opendrive reads large files and builds its spatial
/// index in parallel) done on this thread: in a pool whose one worker is this thread, so no
/// work is stolen by other threads. Their stealing, and their spinning while idle, would make
/// the coverage an input shows depend on thread timing (`scripts/fuzz.sh --ci` needs the same
/// coverage for the same input).
pub fn on_this_thread<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    thread_local! {
        static POOL: Option<rayon::ThreadPool> = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .use_current_thread()
            .build()
            .ok();
    }
    POOL.with(|pool| match pool {
        Some(pool) => pool.install(f),
        None => f(),
    })
}

/// A hang detector that does not rely on libFuzzer's `-timeout`: its SIGALRM handler
/// allocates, and without a sanitizer's allocator that deadlocks when the alarm interrupts the
/// target inside `malloc` (seen on the distribution target). A thread samples the process's CPU
/// time once a second; when one input has used more than [`HANG_CPU_SECONDS`] of CPU (not wall
/// time: the machine is shared and the fuzzers run at nice 19), it writes the input to
/// `$FUZZ_ARTIFACTS/hang-<hash>` (or `./`) and exits with status 70. `FUZZ_WATCHDOG=off` runs
/// without it (`scripts/fuzz.sh --ci`: each check runs instrumented code, so the coverage an
/// input shows would depend on when the check fell).
pub mod watchdog {
    use std::hash::{DefaultHasher, Hash, Hasher};
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::{Mutex, Once};
    use std::time::Duration;

    /// CPU seconds one input may take before it counts as a hang.
    pub const HANG_CPU_SECONDS: f64 = 10.0;

    static GENERATION: AtomicU64 = AtomicU64::new(0);
    static INPUT: Mutex<Vec<u8>> = Mutex::new(Vec::new());
    static START: Once = Once::new();

    /// Process CPU time (user + system) in seconds, from /proc/self/stat.
    fn cpu_seconds() -> Option<f64> {
        let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
        // Fields after the command name (in parentheses): state is field 3, utime 14, stime 15.
        let rest = &stat[stat.rfind(')')? + 2..];
        let fields: Vec<&str> = rest.split(' ').collect();
        let utime: f64 = fields.get(11)?.parse().ok()?;
        let stime: f64 = fields.get(12)?.parse().ok()?;
        // Clock ticks per second: 100 on Linux (USER_HZ).
        Some((utime + stime) / 100.0)
    }

    fn watch() {
        let mut generation = GENERATION.load(Ordering::Relaxed);
        let mut since = cpu_seconds().unwrap_or(0.0);
        loop {
            std::thread::sleep(Duration::from_secs(1));
            let now_generation = GENERATION.load(Ordering::Relaxed);
            let now = cpu_seconds().unwrap_or(since);
            if now_generation != generation {
                generation = now_generation;
                since = now;
                continue;
            }
            if now - since > HANG_CPU_SECONDS {
                let input = INPUT.lock().map(|v| v.clone()).unwrap_or_default();
                let mut h = DefaultHasher::new();
                input.hash(&mut h);
                let dir = std::env::var("FUZZ_ARTIFACTS").unwrap_or_else(|_| ".".into());
                let path = format!("{dir}/hang-{:016x}", h.finish());
                let written = std::fs::write(&path, &input).is_ok();
                eprintln!(
                    "==WATCHDOG== one input ran over {HANG_CPU_SECONDS} s of CPU; {} {path}",
                    if written {
                        "written to"
                    } else {
                        "could not write"
                    }
                );
                std::process::exit(70);
            }
        }
    }

    /// Marks the start of an input (call first in the fuzz target).
    pub fn start(data: &[u8]) {
        START.call_once(|| {
            if std::env::var_os("FUZZ_WATCHDOG").is_none_or(|v| v != "off") {
                std::thread::spawn(watch);
            }
        });
        if let Ok(mut v) = INPUT.lock() {
            v.clear();
            v.extend_from_slice(data);
        }
        GENERATION.fetch_add(1, Ordering::Relaxed);
    }
}
