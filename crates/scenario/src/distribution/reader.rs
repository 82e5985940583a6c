//! Reads an OpenSCENARIO 1.3 §9.5 parameter value distribution file (XSD `OpenScenario` with
//! the `ParameterValueDistributionDefinition` category) into the [`model`](super::model)
//! types, checking every value's domain, with file:line:col on every error.
//!
//! Own small reader over roxmltree rather than the scenario reader: the distribution file is a
//! separate document type with no parameters, catalogs or expressions. Elements outside the
//! XSD's content model are errors; comments and whitespace are ignored.

use std::path::Path;
use std::sync::Arc;

use roxmltree::{Document, Node};

use super::error::{DistributionError, DistributionErrorKind as Kind};
use super::model::{
    DeterministicKind, DeterministicParameterDistribution,
    DeterministicSingleParameterDistributionType as Single, DistributionDefinition,
    ParameterValueDistribution, Range, Stochastic, StochasticDistribution,
    StochasticDistributionType as Sto,
};
use crate::source::LineIndex;
use crate::SourcePos;

/// Parses distribution-file `text`; `file` names it in errors.
pub fn read_distribution(text: &str, file: &Path) -> Result<ParameterValueDistribution> {
    let doc = Document::parse(text).map_err(|e| {
        let p = e.pos();
        let pos = SourcePos::new(Arc::from(file), p.row, p.col);
        let message = pos.strip_from(&e.to_string()).to_owned();
        DistributionError::new(Kind::Xml { message }, pos)
    })?;
    let reader = Reader {
        doc: &doc,
        file: Arc::from(file),
        lines: LineIndex::new(doc.input_text()),
    };
    reader.open_scenario(doc.root_element())
}

struct Reader<'d, 'i> {
    doc: &'d Document<'i>,
    file: Arc<Path>,
    lines: LineIndex,
}

type Result<T> = std::result::Result<T, DistributionError>;

impl<'d, 'i> Reader<'d, 'i> {
    fn error(&self, kind: Kind, byte: usize) -> DistributionError {
        DistributionError::new(kind, self.pos(byte))
    }

    fn pos(&self, byte: usize) -> SourcePos {
        self.lines.pos(&self.file, self.doc.input_text(), byte)
    }

    fn node_pos(&self, node: Node<'d, 'i>) -> SourcePos {
        self.pos(node.range().start)
    }

    fn unexpected(&self, expected: &str, found: Node<'d, 'i>) -> DistributionError {
        let kind = Kind::UnexpectedElement {
            expected: expected.to_owned(),
            found: found.tag_name().name().to_owned(),
        };
        self.error(kind, found.range().start)
    }

    /// The element children of `node`.
    fn children(node: Node<'d, 'i>) -> impl Iterator<Item = Node<'d, 'i>> {
        node.children().filter(Node::is_element)
    }

    /// The one child named `name`, which must be `node`'s only element child.
    fn only_child(&self, node: Node<'d, 'i>, name: &'static str) -> Result<Node<'d, 'i>> {
        let mut children = Self::children(node);
        let child = children.next().ok_or_else(|| self.missing(node, name))?;
        if child.tag_name().name() != name {
            return Err(self.unexpected(&format!("<{name}>"), child));
        }
        if let Some(extra) = children.next() {
            return Err(self.unexpected(
                &format!("no further element in <{}>", node.tag_name().name()),
                extra,
            ));
        }
        Ok(child)
    }

    fn missing(&self, parent: Node<'d, 'i>, expected: &'static str) -> DistributionError {
        let kind = Kind::MissingElement {
            parent: parent.tag_name().name().to_owned(),
            expected,
        };
        self.error(kind, parent.range().start)
    }

    fn attr(&self, node: Node<'d, 'i>, name: &'static str) -> Result<&'d str> {
        node.attribute(name).ok_or_else(|| {
            let kind = Kind::MissingAttribute {
                element: node.tag_name().name().to_owned(),
                attribute: name,
            };
            self.error(kind, node.range().start)
        })
    }

    fn invalid(
        &self,
        node: Node<'d, 'i>,
        name: &'static str,
        expected: &'static str,
    ) -> DistributionError {
        let attribute = node.attributes().find(|a| a.name() == name);
        let found = attribute.map_or("", |a| a.value()).to_owned();
        let byte = attribute.map_or(node.range().start, |a| a.range().start);
        let kind = Kind::InvalidAttribute {
            element: node.tag_name().name().to_owned(),
            attribute: name,
            expected,
            found,
        };
        self.error(kind, byte)
    }

    /// A double attribute satisfying `check`, described by `expected`.
    fn double(
        &self,
        node: Node<'d, 'i>,
        name: &'static str,
        expected: &'static str,
        check: fn(f64) -> bool,
    ) -> Result<f64> {
        match self.attr(node, name)?.trim().parse::<f64>() {
            Ok(v) if v.is_finite() && check(v) => Ok(v),
            _ => Err(self.invalid(node, name, expected)),
        }
    }

    fn optional_double(&self, node: Node<'d, 'i>, name: &'static str) -> Result<Option<f64>> {
        match node.attribute(name) {
            None => Ok(None),
            Some(_) => self
                .double(node, name, "a finite number", |_| true)
                .map(Some),
        }
    }

    /// XSD `OpenScenario`: `FileHeader` then `ParameterValueDistribution`.
    fn open_scenario(&self, root: Node<'d, 'i>) -> Result<ParameterValueDistribution> {
        if !matches!(root.tag_name().name(), "OpenSCENARIO" | "OpenScenario") {
            return Err(self.unexpected("<OpenSCENARIO>", root));
        }
        let mut distribution = None;
        for child in Self::children(root) {
            match child.tag_name().name() {
                "FileHeader" => {}
                "ParameterValueDistribution" if distribution.is_none() => {
                    distribution = Some(self.parameter_value_distribution(child)?);
                }
                _ => {
                    return Err(
                        self.unexpected("<FileHeader> or <ParameterValueDistribution>", child)
                    )
                }
            }
        }
        distribution.ok_or_else(|| self.missing(root, "ParameterValueDistribution"))
    }

    /// XSD `ParameterValueDistribution`: `ScenarioFile`, then `Deterministic` or `Stochastic`.
    fn parameter_value_distribution(
        &self,
        node: Node<'d, 'i>,
    ) -> Result<ParameterValueDistribution> {
        let mut children = Self::children(node);
        let file = children
            .next()
            .ok_or_else(|| self.missing(node, "ScenarioFile"))?;
        if file.tag_name().name() != "ScenarioFile" {
            return Err(self.unexpected("<ScenarioFile>", file));
        }
        let scenario_file = self.attr(file, "filepath")?.to_owned();
        let definition_node = children
            .next()
            .ok_or_else(|| self.missing(node, "Deterministic"))?;
        let definition = match definition_node.tag_name().name() {
            "Deterministic" => {
                DistributionDefinition::Deterministic(self.deterministic(definition_node)?)
            }
            "Stochastic" => DistributionDefinition::Stochastic(self.stochastic(definition_node)?),
            _ => return Err(self.unexpected("<Deterministic> or <Stochastic>", definition_node)),
        };
        if let Some(extra) = children.next() {
            return Err(
                self.unexpected("no further element in <ParameterValueDistribution>", extra)
            );
        }
        Ok(ParameterValueDistribution {
            scenario_file,
            scenario_file_pos: self.node_pos(file),
            definition,
        })
    }

    /// XSD `Deterministic`: any number of single- and multi-parameter distributions.
    fn deterministic(&self, node: Node<'d, 'i>) -> Result<Vec<DeterministicParameterDistribution>> {
        Self::children(node)
            .map(|child| {
                let kind = match child.tag_name().name() {
                    "DeterministicSingleParameterDistribution" => self.single(child)?,
                    "DeterministicMultiParameterDistribution" => {
                        let sets = self.only_child(child, "ValueSetDistribution")?;
                        DeterministicKind::ValueSetDistribution(self.value_sets(sets)?)
                    }
                    _ => {
                        return Err(self.unexpected(
                            "<DeterministicSingleParameterDistribution> or <DeterministicMultiParameterDistribution>",
                            child,
                        ))
                    }
                };
                Ok(DeterministicParameterDistribution { kind, pos: self.node_pos(child) })
            })
            .collect()
    }

    /// XSD `DeterministicSingleParameterDistribution`.
    fn single(&self, node: Node<'d, 'i>) -> Result<DeterministicKind> {
        let parameter_name = self.attr(node, "parameterName")?.to_owned();
        let child = Self::children(node)
            .next()
            .ok_or_else(|| self.missing(node, "DistributionSet"))?;
        let values = match child.tag_name().name() {
            "DistributionSet" => {
                let elements = self.elements(child, "Element")?;
                let values = elements
                    .iter()
                    .map(|e| self.attr(*e, "value").map(str::to_owned));
                Single::DistributionSet(values.collect::<Result<_>>()?)
            }
            "DistributionRange" => {
                let range = self.range(self.only_child(child, "Range")?)?;
                let step_width = self.double(child, "stepWidth", "a number > 0", |v| v > 0.0)?;
                Single::DistributionRange { range, step_width }
            }
            "UserDefinedDistribution" => return Err(self.user_defined(child)),
            _ => {
                return Err(self.unexpected(
                    "<DistributionSet>, <DistributionRange> or <UserDefinedDistribution>",
                    child,
                ))
            }
        };
        if let Some(extra) = Self::children(node).nth(1) {
            return Err(self.unexpected(
                "no further element in <DeterministicSingleParameterDistribution>",
                extra,
            ));
        }
        Ok(DeterministicKind::Single {
            parameter_name,
            values,
        })
    }

    /// One or more children of `node`, all named `name`.
    fn elements(&self, node: Node<'d, 'i>, name: &'static str) -> Result<Vec<Node<'d, 'i>>> {
        let children: Vec<_> = Self::children(node).collect();
        if children.is_empty() {
            return Err(self.missing(node, name));
        }
        if let Some(other) = children.iter().find(|c| c.tag_name().name() != name) {
            return Err(self.unexpected(&format!("<{name}>"), *other));
        }
        Ok(children)
    }

    /// XSD `ValueSetDistribution`: `ParameterValueSet`s of `ParameterAssignment`s.
    fn value_sets(&self, node: Node<'d, 'i>) -> Result<Vec<Vec<(String, String)>>> {
        self.elements(node, "ParameterValueSet")?
            .into_iter()
            .map(|set| {
                self.elements(set, "ParameterAssignment")?
                    .into_iter()
                    .map(|a| {
                        Ok((
                            self.attr(a, "parameterRef")?.to_owned(),
                            self.attr(a, "value")?.to_owned(),
                        ))
                    })
                    .collect()
            })
            .collect()
    }

    /// XSD `Range`: finite limits with lowerLimit ≤ upperLimit.
    fn range(&self, node: Node<'d, 'i>) -> Result<Range> {
        let lower_limit = self.double(node, "lowerLimit", "a finite number", |_| true)?;
        let upper_limit = self.double(node, "upperLimit", "a finite number", |_| true)?;
        if upper_limit < lower_limit {
            return Err(self.invalid(node, "upperLimit", "a number ≥ lowerLimit"));
        }
        Ok(Range {
            lower_limit,
            upper_limit,
        })
    }

    fn optional_range(&self, node: Node<'d, 'i>) -> Result<Option<Range>> {
        match Self::children(node).next() {
            None => Ok(None),
            Some(child) => self
                .only_child(node, "Range")
                .and_then(|_| self.range(child))
                .map(Some),
        }
    }

    fn user_defined(&self, node: Node<'d, 'i>) -> DistributionError {
        let kind = node.attribute("type").unwrap_or("").to_owned();
        self.error(
            Kind::Unsupported {
                element: node.tag_name().name().to_owned(),
                kind,
            },
            node.range().start,
        )
    }

    /// XSD `Stochastic`.
    fn stochastic(&self, node: Node<'d, 'i>) -> Result<Stochastic> {
        let runs = self.attr(node, "numberOfTestRuns")?;
        let number_of_test_runs = runs
            .trim()
            .parse::<u32>()
            .map_err(|_| self.invalid(node, "numberOfTestRuns", "an unsignedInt"))?;
        let random_seed = self.optional_double(node, "randomSeed")?;
        let distributions = self
            .elements(node, "StochasticDistribution")?
            .into_iter()
            .map(|child| {
                Ok(StochasticDistribution {
                    parameter_name: self.attr(child, "parameterName")?.to_owned(),
                    kind: self.stochastic_type(self.only_child_any(child)?)?,
                    pos: self.node_pos(child),
                })
            })
            .collect::<Result<_>>()?;
        let pos = node
            .attributes()
            .find(|a| a.name() == "numberOfTestRuns")
            .map_or(node.range().start, |a| a.range().start);
        Ok(Stochastic {
            number_of_test_runs,
            random_seed,
            distributions,
            pos: self.pos(pos),
        })
    }

    /// The single element child of `node`, whatever its name.
    fn only_child_any(&self, node: Node<'d, 'i>) -> Result<Node<'d, 'i>> {
        let mut children = Self::children(node);
        let child = children
            .next()
            .ok_or_else(|| self.missing(node, "NormalDistribution"))?;
        if let Some(extra) = children.next() {
            return Err(self.unexpected(
                &format!("no further element in <{}>", node.tag_name().name()),
                extra,
            ));
        }
        Ok(child)
    }

    /// XSD group `StochasticDistributionType`.
    fn stochastic_type(&self, node: Node<'d, 'i>) -> Result<Sto> {
        let non_negative = |v: f64| v >= 0.0;
        let positive = |v: f64| v > 0.0;
        Ok(match node.tag_name().name() {
            "NormalDistribution" => Sto::NormalDistribution {
                expected_value: self.double(node, "expectedValue", "a finite number", |_| true)?,
                variance: self.double(node, "variance", "a number ≥ 0", non_negative)?,
                range: self.optional_range(node)?,
            },
            "LogNormalDistribution" => Sto::LogNormalDistribution {
                expected_value: self.double(node, "expectedValue", "a number > 0", positive)?,
                variance: self.double(node, "variance", "a number ≥ 0", non_negative)?,
                range: self.optional_range(node)?,
            },
            "UniformDistribution" => {
                Sto::UniformDistribution(self.range(self.only_child(node, "Range")?)?)
            }
            "PoissonDistribution" => Sto::PoissonDistribution {
                expected_value: self.double(node, "expectedValue", "a number > 0", positive)?,
                range: self.optional_range(node)?,
            },
            "Histogram" => {
                let bins = self.elements(node, "Bin")?;
                let bins = bins
                    .into_iter()
                    .map(|bin| {
                        let weight = self.double(bin, "weight", "a number ≥ 0", non_negative)?;
                        Ok((self.range(self.only_child(bin, "Range")?)?, weight))
                    })
                    .collect::<Result<Vec<_>>>()?;
                self.check_total_weight(node, bins.iter().map(|b| b.1))?;
                Sto::Histogram(bins)
            }
            "ProbabilityDistributionSet" => {
                let elements = self.elements(node, "Element")?;
                let elements = elements
                    .into_iter()
                    .map(|e| {
                        let weight = self.double(e, "weight", "a number ≥ 0", non_negative)?;
                        Ok((self.attr(e, "value")?.to_owned(), weight))
                    })
                    .collect::<Result<Vec<_>>>()?;
                self.check_total_weight(node, elements.iter().map(|e| e.1))?;
                Sto::ProbabilityDistributionSet(elements)
            }
            "UserDefinedDistribution" => return Err(self.user_defined(node)),
            _ => {
                return Err(self.unexpected("one of the StochasticDistributionType elements", node))
            }
        })
    }

    /// The weights of a histogram or probability set must not all be 0.
    fn check_total_weight(
        &self,
        node: Node<'d, 'i>,
        weights: impl Iterator<Item = f64>,
    ) -> Result<()> {
        let total: f64 = weights.sum();
        if total > 0.0 && total.is_finite() {
            return Ok(());
        }
        let kind = Kind::InvalidAttribute {
            element: node.tag_name().name().to_owned(),
            attribute: "weight",
            expected: "weights with a positive, finite sum",
            found: total.to_string(),
        };
        Err(self.error(kind, node.range().start))
    }
}
