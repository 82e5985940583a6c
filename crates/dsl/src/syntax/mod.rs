//! Syntax of the OpenSCENARIO DSL 2.1: lexer, parser, concrete syntax tree, formatting.
