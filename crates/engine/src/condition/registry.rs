//! The registry of user-defined values (OpenSCENARIO 1.3 §7.6.2, XSD
//! `UserDefinedValueCondition`: "a value provided by an external source … compared to a given
//! value"): external code (a co-simulation, a test harness) sets named values; the runtime
//! answers `ConditionContext::user_defined_value` from it.

use std::collections::BTreeMap;

use scenario::expr::Value;

/// Named values set from outside the scenario. Ordered by name, so iteration is
/// deterministic.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct UserValueRegistry {
    values: BTreeMap<String, Value>,
}

impl UserValueRegistry {
    /// An empty registry.
    pub fn new() -> Self {
        Self::default()
    }

    /// Sets `name` to `value`, returning the value it replaces.
    pub fn set(&mut self, name: impl Into<String>, value: Value) -> Option<Value> {
        self.values.insert(name.into(), value)
    }

    /// The current value of `name`.
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.values.get(name)
    }

    /// Removes `name`, returning its value.
    pub fn remove(&mut self, name: &str) -> Option<Value> {
        self.values.remove(name)
    }

    /// All values, by name.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.values.iter().map(|(k, v)| (k.as_str(), v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_get_replace_remove() {
        let mut r = UserValueRegistry::new();
        assert_eq!(r.set("b", Value::Double(1.5)), None);
        assert_eq!(r.set("a", Value::Bool(true)), None);
        assert_eq!(r.set("b", Value::Double(2.5)), Some(Value::Double(1.5)));
        assert_eq!(r.get("b"), Some(&Value::Double(2.5)));
        let names: Vec<&str> = r.iter().map(|(k, _)| k).collect();
        assert_eq!(names, ["a", "b"]);
        assert_eq!(r.remove("a"), Some(Value::Bool(true)));
        assert_eq!(r.get("a"), None);
    }
}
