//! OpenSCENARIO 1.3 §9.2 parameter expressions `${…}`: lexer, parser and evaluator.
