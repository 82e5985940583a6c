//! Writing a message of the ground truth over last frame's copy of it, so that a run whose
//! entity set does not change allocates nothing per frame (issue 17).
//!
//! prost messages own their strings and repeated fields. Building a fresh `MovingObject` per
//! entity and frame costs about ten allocations (its source reference's three strings and two
//! vectors, the lane list, the id's key); keeping last frame's message and overwriting it costs
//! none once the buffers have their size.
//!
//! The rule that keeps a reused message byte-identical to a fresh one: a filler takes the
//! buffers it reuses *out* of the old message ([`std::mem::take`]), fills them, and then
//! assigns a whole new struct literal built from them and `..Default::default()`. Every field
//! the filler does not name is so reset to its default, exactly as in a fresh message; the
//! defaults' empty `Vec`s and `None`s allocate nothing.

use crate::osi3::{ExternalReference, Identifier};

/// `Some(value)` in the buffer of `old` when there is one, else a new string; `None` for
/// `None` (the old buffer is dropped).
pub(crate) fn string(old: Option<String>, value: Option<&str>) -> Option<String> {
    let value = value?;
    let mut s = old.unwrap_or_default();
    if s != value {
        s.clear();
        s.push_str(value);
    }
    Some(s)
}

/// `values` in the buffer of `old`.
pub(crate) fn ids(mut old: Vec<Identifier>, values: &[Identifier]) -> Vec<Identifier> {
    old.clear();
    old.extend_from_slice(values);
    old
}

/// The one `ExternalReference` {`reference`, `type`, `identifier`} as a `source_reference`
/// list, in the buffers of `old` (its first element's strings).
pub(crate) fn source_reference(
    mut old: Vec<ExternalReference>,
    reference: Option<&str>,
    reference_type: &str,
    identifier: &[&str],
) -> Vec<ExternalReference> {
    old.truncate(1);
    let first = old.pop().unwrap_or_default();
    let mut names = first.identifier;
    names.truncate(identifier.len());
    for (k, value) in identifier.iter().enumerate() {
        match names.get_mut(k) {
            Some(name) if name == value => {}
            Some(name) => {
                name.clear();
                name.push_str(value);
            }
            None => names.push((*value).to_owned()),
        }
    }
    old.push(ExternalReference {
        reference: string(first.reference, reference),
        r#type: string(first.r#type, Some(reference_type)),
        identifier: names,
    });
    old
}

/// The element `index` of `list` for overwriting: the one left from the last frame, or a new
/// default pushed at the end (`index` is at most `list.len()`: the elements are written in
/// order).
pub(crate) fn slot<T: Default>(list: &mut Vec<T>, index: usize) -> &mut T {
    if index == list.len() {
        list.push(T::default());
    }
    &mut list[index]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reused_buffers_hold_the_new_values_only() {
        let old = vec![ExternalReference {
            reference: Some("a-much-longer-file-name.xosc".into()),
            r#type: Some("t".into()),
            identifier: vec!["Vehicle".into(), "Ego".into(), "extra".into()],
        }];
        let new = source_reference(
            old,
            Some("s.xosc"),
            "net.asam.openscenario",
            &["Pedestrian", "P1"],
        );
        assert_eq!(
            new,
            vec![ExternalReference {
                reference: Some("s.xosc".into()),
                r#type: Some("net.asam.openscenario".into()),
                identifier: vec!["Pedestrian".into(), "P1".into()],
            }]
        );
        // From nothing: the same as a fresh reference.
        let fresh = source_reference(Vec::new(), None, "x", &["a"]);
        assert_eq!(fresh[0].reference, None);
        assert_eq!(fresh[0].identifier, vec!["a".to_string()]);
        assert_eq!(string(Some("abc".into()), None), None);
        assert_eq!(string(Some("abc".into()), Some("z")).as_deref(), Some("z"));
        let mut list: Vec<u8> = vec![7];
        *slot(&mut list, 1) = 9;
        assert_eq!(list, vec![7, 9]);
    }
}
