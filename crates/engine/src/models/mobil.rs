//! MOBIL, "Minimizing Overall Braking Induced by Lane changes" (A. Kesting, M. Treiber,
//! D. Helbing, "General lane-changing model MOBIL for car-following models", Transportation
//! Research Record 1999, 86–94, 2007): the lane-change decision of a driver on top of a
//! car-following model (here the IDM of [`super::idm`]).
//!
//! With c the changing vehicle, o its follower in the present lane and n its follower in the
//! target lane, a the accelerations now and ã those after the change (each from the
//! car-following model), a change is
//!
//! - **safe** when the new follower need not brake harder than the safe deceleration:
//!   ã_n ≥ −b_safe (the paper's eq. (1)); oscsim asks the same of the changing vehicle
//!   itself, ã_c ≥ −b_safe, so that no change ends in a hard brake behind the new leader;
//! - **worth it** when the own advantage outweighs the others' disadvantage, weighted by the
//!   politeness p, by more than the threshold Δa_th (eq. (2)):
//!   ã_c − a_c + p·[(ã_n − a_n) + (ã_o − a_o)] > Δa_th − Δa_bias towards the keep side
//!   (right under right-hand traffic) and > Δa_th + Δa_bias away from it. This is the
//!   symmetric incentive with the bias of the paper's asymmetric (keep-right) rules, §"Asymmetric
//!   lane-changing rules", as in Treiber & Kesting, "Traffic Flow Dynamics" (2013) §14.3.
//!
//! A follower that does not exist contributes nothing (its accelerations are taken as equal).
//! Defaults are the paper's: p = 0.5, Δa_th = 0.1 m/s², b_safe = 4 m/s², Δa_bias = 0.3 m/s².

use opendrive::Real;

/// The MOBIL parameters (SI units), named as the `Property` names of a `mobil` controller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MobilParameters {
    /// `politeness` p (dimensionless, 0 egoistic … 1 altruistic).
    pub politeness: Real,
    /// `changeThreshold` Δa_th (m/s²).
    pub change_threshold: Real,
    /// `safeDeceleration` b_safe (m/s², positive).
    pub safe_deceleration: Real,
    /// `rightBias` Δa_bias (m/s²): the bias towards the keep side of the road's traffic rule
    /// (the right lane under right-hand traffic, the left under left-hand traffic).
    pub right_bias: Real,
}

impl Default for MobilParameters {
    /// The values of Kesting, Treiber and Helbing (2007).
    fn default() -> Self {
        MobilParameters {
            politeness: 0.5,
            change_threshold: 0.1,
            safe_deceleration: 4.0,
            right_bias: 0.3,
        }
    }
}

/// A follower's acceleration before and after the change (m/s²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowerChange {
    /// Now (a).
    pub before: Real,
    /// After the change (ã).
    pub after: Real,
}

/// The accelerations one candidate lane change is judged by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneChangeCandidate {
    /// The changing vehicle: now and in the target lane.
    pub own: FollowerChange,
    /// The follower in the present lane (o), if any: behind the changer now, behind the
    /// changer's present leader after the change.
    pub old_follower: Option<FollowerChange>,
    /// The follower in the target lane (n), if any: behind its present leader now, behind the
    /// changer after the change.
    pub new_follower: Option<FollowerChange>,
    /// The target lane lies towards the keep side of the road's traffic rule.
    pub toward_keep_side: bool,
}

/// The verdict on one candidate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Verdict {
    /// The safety criterion holds.
    pub safe: bool,
    /// The incentive minus the threshold (m/s²): the change is worth it when positive.
    pub margin: Real,
}

impl Verdict {
    /// Safe and worth it.
    pub fn change(&self) -> bool {
        self.safe && self.margin > 0.0
    }
}

impl MobilParameters {
    /// The safety criterion's part for the changing vehicle: ã_c ≥ −b_safe (module doc). A
    /// caller may stop weighing a candidate where it fails: the verdict is no change.
    #[inline]
    pub fn safe_for_changer(&self, own_after: Real) -> bool {
        own_after >= -self.safe_deceleration
    }

    /// The safety criterion's part for the new follower: not ã_n < −b_safe (module doc).
    #[inline]
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // written so: a NaN is not "harder than b_safe"
    pub fn safe_for_follower(&self, new_follower_after: Real) -> bool {
        !(new_follower_after < -self.safe_deceleration)
    }

    /// Judges `c` by the safety and incentive criteria (module doc).
    pub fn judge(&self, c: &LaneChangeCandidate) -> Verdict {
        let gain = |f: Option<FollowerChange>| f.map_or(0.0, |f| f.after - f.before);
        let safe = self.safe_for_changer(c.own.after)
            && !matches!(c.new_follower, Some(n) if !self.safe_for_follower(n.after));
        let incentive = c.own.after - c.own.before
            + self.politeness * (gain(c.new_follower) + gain(c.old_follower));
        let threshold = if c.toward_keep_side {
            self.change_threshold - self.right_bias
        } else {
            self.change_threshold + self.right_bias
        };
        Verdict {
            safe,
            margin: incentive - threshold,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::idm::{IdmParameters, Leader};

    const EPS: Real = 1e-12;

    fn change(before: Real, after: Real) -> FollowerChange {
        FollowerChange { before, after }
    }

    #[test]
    fn incentive_by_hand() {
        // own +1.0, new follower −0.4, old follower +0.2, p = 0.5:
        // 1.0 + 0.5·(−0.4 + 0.2) = 0.9; to the left (away from the keep side) the threshold is
        // 0.1 + 0.3 = 0.4 → margin 0.5; to the right 0.1 − 0.3 = −0.2 → margin 1.1.
        let p = MobilParameters::default();
        let mut c = LaneChangeCandidate {
            own: change(-0.5, 0.5),
            old_follower: Some(change(-0.1, 0.1)),
            new_follower: Some(change(0.2, -0.2)),
            toward_keep_side: false,
        };
        let v = p.judge(&c);
        assert!(v.safe && (v.margin - 0.5).abs() < EPS, "{v:?}");
        c.toward_keep_side = true;
        assert!((p.judge(&c).margin - 1.1).abs() < EPS);
    }

    #[test]
    fn unsafe_when_the_new_follower_brakes_harder_than_allowed() {
        let p = MobilParameters::default();
        let c = LaneChangeCandidate {
            own: change(-1.0, 0.7),
            old_follower: None,
            new_follower: Some(change(0.0, -4.01)),
            toward_keep_side: false,
        };
        let v = p.judge(&c);
        assert!(!v.safe && !v.change());
        // At exactly −b_safe the change is still safe (ã_n ≥ −b_safe).
        let edge = LaneChangeCandidate {
            new_follower: Some(change(0.0, -4.0)),
            ..c
        };
        assert!(p.judge(&edge).safe);
    }

    /// Issue 13, the model level: a car at 30 m/s (v0 = 33.3 m/s) 40 m behind a truck at
    /// 22 m/s in the right lane, with the left lane empty, changes left; with a car in the left
    /// lane at 36 m/s 20 m behind it does not, because that car would brake harder than
    /// b_safe. Worked out with the IDM defaults (s0 = 2, T = 1.6, a = 0.73, b = 1.67,
    /// √(ab) = 1.104129):
    ///
    /// - now: s* = 2 + 30·1.6 + 30·8/2.208258 = 50 + 108.684 = 158.684 m, behind the truck at
    ///   40 m: a_c = 0.73·(1 − 0.9^4 − (158.684/40)²) = 0.73·(0.3439 − 15.7378) = −11.238;
    /// - left lane empty: ã_c = 0.73·0.3439 = 0.251; no followers: margin
    ///   = 0.251 + 11.238 − 0.4 > 0, a change;
    /// - a car at 36 m/s, 20 m behind (its gap to the changer 20 m): s* = 2 + 57.6 +
    ///   36·6/2.208258 = 59.6 + 97.814 = 157.414 m; ã_n = 0.73·(1 − (36/33.33)^4 −
    ///   (157.414/20)²) = 0.73·(1 − 1.3605 − 61.947) ≈ −45.5 < −4: unsafe.
    #[test]
    fn changes_past_a_slow_truck_only_when_safe() {
        let idm = IdmParameters::default();
        let mobil = MobilParameters::default();
        let truck = Leader {
            gap: 40.0,
            speed: 22.0,
        };
        let a_c = idm.acceleration(30.0, Some(truck));
        assert!((a_c - (-11.238)).abs() < 1e-2, "{a_c}");
        let free = idm.acceleration(30.0, None);
        let free_lane = LaneChangeCandidate {
            own: change(a_c, free),
            old_follower: None,
            new_follower: None,
            toward_keep_side: false,
        };
        assert!(mobil.judge(&free_lane).change());

        let fast = |gap| Leader { gap, speed: 30.0 };
        let n_after = idm.acceleration(36.0, Some(fast(20.0)));
        assert!(n_after < -mobil.safe_deceleration, "{n_after}");
        let blocked = LaneChangeCandidate {
            new_follower: Some(change(idm.acceleration(36.0, None), n_after)),
            ..free_lane
        };
        assert!(!mobil.judge(&blocked).change());
    }
}
