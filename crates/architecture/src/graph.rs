//! Cycles of a directed graph of modules: its strongly connected components of more than one
//! node (Tarjan, "Depth-first search and linear graph algorithms", SIAM J. Comput. 1972), and
//! the two-way pairs (`a` uses `b` and `b` uses `a`) inside them.

use std::collections::{BTreeMap, BTreeSet};

/// One cycle: a strongly connected component of two or more modules.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cycle {
    /// Its modules, sorted.
    pub modules: BTreeSet<String>,
    /// The uses between them (each edge of the graph with both ends in the component).
    pub edges: BTreeSet<(String, String)>,
    /// The pairs that use each other, `(a, b)` with `a < b`.
    pub two_way: BTreeSet<(String, String)>,
}

/// The cycles of the graph `edges` over `nodes`, ordered by their first module.
pub fn cycles(nodes: &BTreeSet<String>, edges: &BTreeSet<(String, String)>) -> Vec<Cycle> {
    let mut adj: BTreeMap<&str, Vec<&str>> = nodes.iter().map(|n| (n.as_str(), vec![])).collect();
    for (a, b) in edges {
        adj.entry(a).or_default().push(b);
        adj.entry(b).or_default();
    }
    let mut t = Tarjan {
        adj: &adj,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        next: 0,
        components: Vec::new(),
    };
    for n in adj.keys() {
        if !t.index.contains_key(n) {
            t.visit(n);
        }
    }
    let mut out: Vec<Cycle> = t
        .components
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|c| {
            let modules: BTreeSet<String> = c.iter().map(|s| (*s).to_owned()).collect();
            let inside: BTreeSet<(String, String)> = edges
                .iter()
                .filter(|(a, b)| modules.contains(a) && modules.contains(b))
                .cloned()
                .collect();
            let two_way = inside
                .iter()
                .filter(|(a, b)| a < b && inside.contains(&(b.clone(), a.clone())))
                .cloned()
                .collect();
            Cycle {
                modules,
                edges: inside,
                two_way,
            }
        })
        .collect();
    out.sort_by(|a, b| a.modules.cmp(&b.modules));
    out
}

struct Tarjan<'a> {
    adj: &'a BTreeMap<&'a str, Vec<&'a str>>,
    index: BTreeMap<&'a str, usize>,
    low: BTreeMap<&'a str, usize>,
    stack: Vec<&'a str>,
    on_stack: BTreeSet<&'a str>,
    next: usize,
    components: Vec<Vec<&'a str>>,
}

impl<'a> Tarjan<'a> {
    fn visit(&mut self, v: &'a str) {
        self.index.insert(v, self.next);
        self.low.insert(v, self.next);
        self.next += 1;
        self.stack.push(v);
        self.on_stack.insert(v);
        let adj = self.adj;
        for &w in adj.get(v).map_or(&[][..], |x| x.as_slice()) {
            if !self.index.contains_key(w) {
                self.visit(w);
                let lw = self.low[w];
                let lv = self.low.get_mut(v).expect("v was indexed above");
                *lv = (*lv).min(lw);
            } else if self.on_stack.contains(w) {
                let iw = self.index[w];
                let lv = self.low.get_mut(v).expect("v was indexed above");
                *lv = (*lv).min(iw);
            }
        }
        if self.low[v] == self.index[v] {
            let mut component = Vec::new();
            while let Some(w) = self.stack.pop() {
                self.on_stack.remove(w);
                component.push(w);
                if w == v {
                    break;
                }
            }
            self.components.push(component);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn graph(edges: &[(&str, &str)]) -> (BTreeSet<String>, BTreeSet<(String, String)>) {
        let e: BTreeSet<(String, String)> = edges
            .iter()
            .map(|(a, b)| ((*a).to_owned(), (*b).to_owned()))
            .collect();
        let n = e.iter().flat_map(|(a, b)| [a.clone(), b.clone()]).collect();
        (n, e)
    }

    #[test]
    fn a_three_cycle_and_a_two_way_pair_are_two_components() {
        // a → b → c → a is one component (3 edges, no pair both ways); d ↔ e another (one
        // pair); f hangs off c and is in none.
        let (n, e) = graph(&[
            ("a", "b"),
            ("b", "c"),
            ("c", "a"),
            ("c", "f"),
            ("d", "e"),
            ("e", "d"),
        ]);
        let c = cycles(&n, &e);
        assert_eq!(c.len(), 2);
        assert_eq!(c[0].modules.len(), 3);
        assert_eq!(c[0].edges.len(), 3);
        assert!(c[0].two_way.is_empty());
        assert_eq!(c[1].modules.len(), 2);
        assert_eq!(c[1].two_way.len(), 1);
    }

    #[test]
    fn a_chain_has_no_cycle() {
        let (n, e) = graph(&[("a", "b"), ("b", "c"), ("a", "c")]);
        assert!(cycles(&n, &e).is_empty());
    }
}
