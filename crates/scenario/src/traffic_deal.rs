//! The dealing rule of random traffic: where the members of a group of noise vehicles are put
//! when the group is created (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1, non-normative: "the group
//! defines the initial conditions of actors in the scenario, meaning their creation and
//! destruction"). The standard gives no rule; this is oscsim's (docs/dsl.md, the random
//! traffic row), in one place for the two that deal: the DSL plan, where it knows every other
//! vehicle's place at the creation, and the engine's [`crate::PrivateAction::CreateRandomTraffic`],
//! where only the run knows them (a creation after a run-time condition, or beside a vehicle
//! the engine moves).
//!
//! The rule, given the lanes the members may be dealt to ([`LaneSpan`]s, each one driving lane
//! over a stretch of the roads, measured along its direction of travel), the other vehicles
//! ([`Occupant`]s) and the members' start speeds:
//!
//! - the gap between any two vehicles in a lane (bumper to bumper) is at least the IDM's
//!   s0 + v_max·T ([`IDM_S0`], [`IDM_T`]), v_max the fastest start speed on the road, the
//!   others' included ([`gap`]);
//! - the free stretches are the spans less every occupant of that lane and direction with
//!   the gap either side ([`free_stretches`]);
//! - the members are dealt one at a time, a stretch drawn with a weight equal to the room
//!   left in it, then each stretch's members are spread uniformly over its slack (n draws in
//!   [0, F] sorted, F the stretch's length less the members' lengths and gaps): every
//!   arrangement at the minimum gap equally likely ([`deal`]);
//! - no stretch with room for the next member: [`NoRoom`], how many fitted.
//!
//! The draws come from the caller (the plan's stream of the run's seed, or [`Draws`] from a
//! seed the plan drew for the engine), so the same seed gives the same bytes.

use rand::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The IDM's minimum gap s0 (m): the engine's default (Treiber, Hennecke and Helbing 2000).
pub const IDM_S0: f64 = 2.0;
/// The IDM's time headway T (s): the engine's default.
pub const IDM_T: f64 = 1.6;

/// One driving lane over a stretch of the roads: its direction (`against`: driven in −s, the
/// distances then u = L − s along the direction of travel), its OpenDRIVE lane id, and the
/// stretch `from`..`to` (m, along the direction of travel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneSpan {
    /// Driven against s.
    pub against: bool,
    /// The lane id.
    pub lane: i32,
    /// Where the stretch starts (m).
    pub from: f64,
    /// Where it ends (m).
    pub to: f64,
}

/// A vehicle already on the road: its direction and lane as a [`LaneSpan`]'s, its rear and
/// front bumpers along that direction (m), and its speed (m/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Occupant {
    /// In a lane driven against s.
    pub against: bool,
    /// The lane id.
    pub lane: i32,
    /// Its rear bumper (m).
    pub rear: f64,
    /// Its front bumper (m).
    pub front: f64,
    /// Its speed (m/s).
    pub speed: f64,
}

/// A member to deal: its length and the distance from its rear bumper to its reference point
/// (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Member {
    /// Bounding box length (m).
    pub length: f64,
    /// Rear bumper to reference point (m).
    pub rear: f64,
}

/// Where a member is dealt: its index among the members, the lane's direction and id, and its
/// reference point along the lane's direction of travel (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dealt {
    /// Index into the members.
    pub member: usize,
    /// In a lane driven against s.
    pub against: bool,
    /// The lane id.
    pub lane: i32,
    /// The reference point (m; u against s).
    pub s: f64,
}

/// No room for every member: how many fitted, at which gap (m), set by which fastest start
/// speed (m/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NoRoom {
    /// Members dealt before the one that found no room.
    pub fit: usize,
    /// The gap between vehicles (m).
    pub gap: f64,
    /// The fastest start speed (m/s).
    pub v_max: f64,
}

impl NoRoom {
    /// The error's two halves, "expected …" and "found …", for `n` members of group `g`: the
    /// same words from the plan and the engine.
    pub fn message(&self, n: usize, g: &str) -> (String, String) {
        (
            format!(
                "room on the plan's driving lanes for the {n} members of random traffic `{g}` (each its length plus a gap of {:.1} m to the next vehicle: s0 + v·T at the fastest start speed {:.2} m/s)",
                self.gap, self.v_max
            ),
            format!("room for {}", self.fit),
        )
    }
}

/// The gap between vehicles s0 + v_max·T (m) and v_max (m/s), the fastest of `speeds` and the
/// occupants' speeds.
pub fn gap(speeds: &[f64], others: &[Occupant]) -> (f64, f64) {
    let v_max = speeds
        .iter()
        .chain(others.iter().map(|o| &o.speed))
        .fold(0.0_f64, |a, &b| a.max(b));
    (IDM_S0 + v_max * IDM_T, v_max)
}

/// A free stretch of a lane and the members dealt to it.
#[derive(Debug, Clone)]
struct Stretch {
    span: LaneSpan,
    members: Vec<usize>,
    used: f64,
}

impl Stretch {
    /// The room left for one more member of length `len` at gap `gap` (m; negative: none).
    fn room(&self, len: f64, gap: f64) -> f64 {
        let between = if self.members.is_empty() { 0.0 } else { gap };
        (self.span.to - self.span.from) - self.used - between - len
    }
}

/// The parts of `spans` (in their order) free of `others` in the same lane and direction by
/// `gap` either side.
pub fn free_stretches(spans: &[LaneSpan], others: &[Occupant], gap: f64) -> Vec<LaneSpan> {
    let mut out = Vec::new();
    for span in spans {
        let mut blocked: Vec<(f64, f64)> = others
            .iter()
            .filter(|o| o.against == span.against && o.lane == span.lane)
            .map(|o| (o.rear - gap, o.front + gap))
            .collect();
        blocked.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (a, b) = (span.from, span.to);
        let mut from = a;
        for (x0, x1) in blocked.into_iter().chain([(b, b)]) {
            if x0.min(b) > from {
                out.push(LaneSpan {
                    from,
                    to: x0.min(b),
                    ..*span
                });
            }
            from = from.max(x1);
        }
    }
    out
}

/// Deals `members` over the free stretches of `spans` among `others` at the gap their start
/// `speeds` and the others' set (module doc), drawing from `uniform` (each draw in [0, 1)):
/// first one stretch per member, then the places within each stretch.
pub fn deal(
    spans: &[LaneSpan],
    others: &[Occupant],
    members: &[Member],
    speeds: &[f64],
    uniform: &mut dyn FnMut() -> f64,
) -> Result<Vec<Dealt>, NoRoom> {
    let (gap, v_max) = gap(speeds, others);
    let mut stretches: Vec<Stretch> = free_stretches(spans, others, gap)
        .into_iter()
        .map(|span| Stretch {
            span,
            members: Vec::new(),
            used: 0.0,
        })
        .collect();
    for (i, m) in members.iter().enumerate() {
        let rooms: Vec<f64> = stretches.iter().map(|s| s.room(m.length, gap)).collect();
        let total: f64 = rooms.iter().filter(|r| **r >= 0.0).sum();
        if !rooms.iter().any(|r| *r >= 0.0) {
            return Err(NoRoom { fit: i, gap, v_max });
        }
        // A stretch drawn with a weight of its room left.
        let mut pick = uniform() * total;
        let mut k = rooms.iter().rposition(|r| *r >= 0.0).unwrap_or(0);
        for (j, r) in rooms.iter().enumerate() {
            if *r < 0.0 {
                continue;
            }
            if pick < *r {
                k = j;
                break;
            }
            pick -= r;
        }
        let st = &mut stretches[k];
        st.used += m.length + if st.members.is_empty() { 0.0 } else { gap };
        st.members.push(i);
    }
    let mut out = Vec::new();
    for st in &stretches {
        let slack = (st.span.to - st.span.from) - st.used;
        let mut u: Vec<f64> = st.members.iter().map(|_| uniform() * slack).collect();
        u.sort_by(f64::total_cmp);
        let mut before = 0.0;
        for (&i, du) in st.members.iter().zip(u) {
            out.push(Dealt {
                member: i,
                against: st.span.against,
                lane: st.span.lane,
                s: st.span.from + du + before + members[i].rear,
            });
            before += members[i].length + gap;
        }
    }
    Ok(out)
}

/// The engine's stream of draws for one dealing, from a seed the plan drew from the run's
/// seed: uniform draws in [0, 1) from the top 53 bits of ChaCha8 (integer-only mapping, the
/// same on every machine).
#[derive(Debug, Clone)]
pub struct Draws(ChaCha8Rng);

impl Draws {
    /// The stream of `seed`.
    pub fn new(seed: u64) -> Self {
        Draws(ChaCha8Rng::seed_from_u64(seed))
    }

    /// A uniform draw in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Float round-off of sums of a few metres (m).
    const TOL: f64 = 1e-9;

    fn span(lane: i32, from: f64, to: f64) -> LaneSpan {
        LaneSpan {
            against: false,
            lane,
            from,
            to,
        }
    }

    #[test]
    fn the_free_stretches_leave_the_gap_either_side_of_an_occupant() {
        // Lane -1 over [0, 100] m, a vehicle from 40 to 44 m at 10 m/s: gap 2 + 16 = 18 m,
        // free [0, 22] and [62, 100]; lane -2 untouched; an oncoming vehicle in lane 1
        // blocks nothing of lane -1.
        let others = [
            Occupant {
                against: false,
                lane: -1,
                rear: 40.0,
                front: 44.0,
                speed: 10.0,
            },
            Occupant {
                against: true,
                lane: 1,
                rear: 0.0,
                front: 100.0,
                speed: 0.0,
            },
        ];
        let (g, v) = gap(&[5.0], &others);
        assert!((g - 18.0).abs() < TOL && (v - 10.0).abs() < TOL, "{g} {v}");
        let free = free_stretches(&[span(-1, 0.0, 100.0), span(-2, 0.0, 100.0)], &others, g);
        let want = [(-1, 0.0, 22.0), (-1, 62.0, 100.0), (-2, 0.0, 100.0)];
        assert_eq!(free.len(), want.len(), "{free:?}");
        for (f, w) in free.iter().zip(want) {
            assert!(f.lane == w.0 && (f.from - w.1).abs() < TOL && (f.to - w.2).abs() < TOL);
        }
    }

    #[test]
    fn members_dealt_keep_the_gap_and_no_room_says_how_many_fit() {
        // Two 4 m members at 10 m/s (gap 18 m) in 30 m: 4 + 18 + 4 = 26 m fits, a third
        // does not (48 m).
        let m = Member {
            length: 4.0,
            rear: 0.5,
        };
        let mut d = Draws::new(7);
        let dealt = deal(
            &[span(-1, 0.0, 30.0)],
            &[],
            &[m, m],
            &[10.0, 10.0],
            &mut || d.uniform(),
        )
        .expect("26 m of 30 m");
        let (a, b) = (dealt[0].s - 0.5, dealt[1].s - 0.5);
        assert!(a >= -TOL && b - (a + 4.0) >= 18.0 - TOL && b + 4.0 <= 30.0 + TOL);
        let err = deal(
            &[span(-1, 0.0, 30.0)],
            &[],
            &[m, m, m],
            &[10.0; 3],
            &mut || d.uniform(),
        )
        .expect_err("48 m in 30 m");
        assert_eq!(err.fit, 2);
        assert!((err.gap - 18.0).abs() < TOL);
    }

    #[test]
    fn the_same_seed_deals_the_same_places() {
        let m = Member {
            length: 4.0,
            rear: 0.5,
        };
        let run = |seed| {
            let mut d = Draws::new(seed);
            deal(
                &[span(-1, 0.0, 500.0), span(-2, 0.0, 500.0)],
                &[],
                &[m; 5],
                &[20.0; 5],
                &mut || d.uniform(),
            )
            .expect("room")
        };
        assert_eq!(run(3), run(3));
        assert_ne!(run(3), run(4));
    }
}
