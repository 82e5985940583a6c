//! Shares of a batch for several processes or machines: shard `I/N` runs the variants whose
//! number is `I` modulo `N` (round robin, so the shares stay even when the cost of a variant
//! grows with its parameters). The shards of one batch are disjoint and together cover every
//! variant; `merge.rs` joins their outputs into what one unsharded run writes.
//!
//! Where the share comes from, first match wins:
//! 1. `--shard I/N` (0 ≤ I < N);
//! 2. a Slurm job array: `SLURM_ARRAY_TASK_ID` minus `SLURM_ARRAY_TASK_MIN` (0 when unset) of
//!    `SLURM_ARRAY_TASK_COUNT` tasks (`sbatch --array=0-(N-1)`);
//! 3. a Kubernetes Indexed Job: `JOB_COMPLETION_INDEX` of `--shards N` (the Job's
//!    `completions`; Kubernetes does not tell the pod the count).
//!
//! Otherwise the process runs every variant.

use crate::error::{Error, ShardErrorKind};

/// One share of a batch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// This shard's number, 0-based.
    pub index: u64,
    /// How many shards share the batch.
    pub count: u64,
}

impl Shard {
    /// The whole batch as one shard.
    pub const ALL: Shard = Shard { index: 0, count: 1 };

    /// Whether variant `variant` belongs to this shard.
    pub fn contains(self, variant: u64) -> bool {
        variant % self.count == self.index
    }

    /// Parses `I/N`.
    pub fn parse(text: &str) -> Result<Shard, Error> {
        let err = || ShardErrorKind {
            expected: "I/N with 0 ≤ I < N",
            found: text.to_owned(),
            source_name: "--shard".into(),
        };
        let (i, n) = text.split_once('/').ok_or_else(err)?;
        let (index, count) = (
            i.trim().parse().map_err(|_| err())?,
            n.trim().parse().map_err(|_| err())?,
        );
        Ok(Shard::checked(index, count).ok_or_else(err)?)
    }

    fn checked(index: u64, count: u64) -> Option<Shard> {
        (count > 0 && index < count).then_some(Shard { index, count })
    }

    /// The shard from `--shard`, else the environment of a Slurm array task or a Kubernetes
    /// Indexed Job (module doc); `env` reads a variable (`std::env::var` in the cli).
    pub fn resolve(
        flag: Option<&str>,
        shards: Option<u64>,
        env: impl Fn(&str) -> Option<String>,
    ) -> Result<Shard, Error> {
        if let Some(text) = flag {
            return Shard::parse(text);
        }
        let number = |name: &str| -> Result<Option<u64>, ShardErrorKind> {
            env(name)
                .map(|v| {
                    v.trim().parse::<u64>().map_err(|_| ShardErrorKind {
                        expected: "a non-negative integer",
                        found: v.clone(),
                        source_name: name.to_owned(),
                    })
                })
                .transpose()
        };
        if let (Some(id), Some(count)) = (
            number("SLURM_ARRAY_TASK_ID")?,
            number("SLURM_ARRAY_TASK_COUNT")?,
        ) {
            let min = number("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
            let index = id.checked_sub(min).unwrap_or(u64::MAX);
            return Ok(Shard::checked(index, count).ok_or(ShardErrorKind {
                expected: "SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN below SLURM_ARRAY_TASK_COUNT",
                found: format!("{id} − {min} of {count}"),
                source_name: "SLURM_ARRAY_TASK_ID".into(),
            })?);
        }
        if let Some(index) = number("JOB_COMPLETION_INDEX")? {
            let Some(count) = shards else {
                return Err(ShardErrorKind {
                    expected:
                        "--shards N with JOB_COMPLETION_INDEX (the Indexed Job's completions)",
                    found: index.to_string(),
                    source_name: "JOB_COMPLETION_INDEX".into(),
                }
                .into());
            };
            return Ok(Shard::checked(index, count).ok_or(ShardErrorKind {
                expected: "JOB_COMPLETION_INDEX below --shards",
                found: format!("{index} of {count}"),
                source_name: "JOB_COMPLETION_INDEX".into(),
            })?);
        }
        Ok(Shard::ALL)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(vars: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |name| {
            vars.iter()
                .find(|(k, _)| *k == name)
                .map(|(_, v)| v.to_string())
        }
    }

    #[test]
    fn three_shards_cover_every_variant_once() {
        let shards: Vec<Shard> = (0..3)
            .map(|i| Shard::parse(&format!("{i}/3")).unwrap())
            .collect();
        for v in 0..100 {
            assert_eq!(
                shards.iter().filter(|s| s.contains(v)).count(),
                1,
                "variant {v}"
            );
        }
        assert!(
            Shard::parse("3/3").is_err()
                && Shard::parse("0/0").is_err()
                && Shard::parse("1").is_err()
        );
    }

    #[test]
    fn the_share_comes_from_the_flag_then_slurm_then_kubernetes() {
        let slurm = [
            ("SLURM_ARRAY_TASK_ID", "12"),
            ("SLURM_ARRAY_TASK_MIN", "10"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
        ];
        assert_eq!(
            Shard::resolve(None, None, env(&slurm)).unwrap(),
            Shard { index: 2, count: 4 }
        );
        assert_eq!(
            Shard::resolve(Some("1/2"), None, env(&slurm)).unwrap(),
            Shard { index: 1, count: 2 }
        );
        let k8s = [("JOB_COMPLETION_INDEX", "5")];
        assert_eq!(
            Shard::resolve(None, Some(8), env(&k8s)).unwrap(),
            Shard { index: 5, count: 8 }
        );
        let e = Shard::resolve(None, None, env(&k8s)).unwrap_err();
        assert!(e.to_string().starts_with("expected --shards N"), "{e}");
        assert_eq!(Shard::resolve(None, None, env(&[])).unwrap(), Shard::ALL);
    }
}
