// Grammar of the ASAM OpenSCENARIO DSL subset that pytest-roadlogic reads.
//
// Written for this project from the language description in the standard (section 7.2) and
// docs/os2-subset.md. The layout is Python-like: the lexer emits NEWLINE tokens, and
// pytest_roadlogic.frontend.lexer.IndentingLexer turns leading whitespace into the INDENT and
// DEDENT tokens declared below and drops line breaks inside (...) and [...]. Keeping that logic in
// Python (not in target-specific @members) keeps this file free of target code.
//
// The generated parser in ../generated is committed. Regenerate it with
//     python -m pytest_roadlogic.frontend.regenerate
// (tests/test_frontend_generated.py fails when it is stale).

grammar OpenScenario2;

tokens { INDENT, DEDENT }

// ---------------------------------------------------------------- parser

oscFile
    : NEWLINE* importStatement* (declaration | NEWLINE)* EOF
    ;

importStatement
    : IMPORT (StringLiteral | dottedName) NEWLINE
    ;

declaration
    : scenarioDeclaration
    ;

scenarioDeclaration
    : SCENARIO scenarioName COLON NEWLINE INDENT scenarioMember+ DEDENT
    ;

// `scenario traffic.overtake:` ties the scenario to an actor type; it is not a namespace.
scenarioName
    : (actorType=identifier DOT)? name=identifier
    ;

scenarioMember
    : fieldDeclaration
    | doDirective
    ;

fieldDeclaration
    : identifier (COMMA identifier)* COLON typeName (ASSIGN expression)? NEWLINE
    ;

typeName
    : identifier
    ;

doDirective
    : DO behavior
    ;

behavior
    : (label=identifier COLON)? (composition | invocation)
    ;

composition
    : compositionOperator (LPAREN argumentList? RPAREN)? COLON NEWLINE INDENT behavior+ DEDENT
    ;

compositionOperator
    : SERIAL
    | PARALLEL
    | ONE_OF
    ;

invocation
    : (actor=identifier DOT)? action=identifier LPAREN argumentList? RPAREN
      (WITH COLON NEWLINE INDENT modifierInvocation+ DEDENT | NEWLINE)
    ;

modifierInvocation
    : (actor=identifier DOT)? name=identifier LPAREN argumentList? RPAREN NEWLINE
    ;

argumentList
    : argument (COMMA argument)*
    ;

argument
    : (name=identifier COLON)? expression
    ;

expression
    : MINUS expression                                   # negation
    | rangeLiteral                                       # rangeExpression
    | PhysicalLiteral                                    # physicalExpression
    | number                                             # numberExpression
    | StringLiteral                                      # stringExpression
    | (TRUE | FALSE)                                     # boolExpression
    | dottedName                                         # nameExpression
    | LPAREN expression RPAREN                           # parenthesised
    ;

// `[10..20]m` (the paper's spelling, unit after the range) and `[10m..20m]` (the standard's).
rangeLiteral
    : LBRACK low=expression DOUBLEDOT high=expression RBRACK unit=identifier?
    ;

number
    : IntLiteral
    | FloatLiteral
    | HexLiteral
    ;

dottedName
    : identifier (DOT identifier)*
    ;

// Words that are keywords elsewhere but usable as names here.
identifier
    : Identifier
    ;

// ---------------------------------------------------------------- lexer

IMPORT    : 'import' ;
SCENARIO  : 'scenario' ;
DO        : 'do' ;
SERIAL    : 'serial' ;
PARALLEL  : 'parallel' ;
ONE_OF    : 'one_of' ;
WITH      : 'with' ;
TRUE      : 'true' ;
FALSE     : 'false' ;

DOUBLEDOT : '..' ;
DOT       : '.' ;
COMMA     : ',' ;
COLON     : ':' ;
ASSIGN    : '=' ;
MINUS     : '-' ;
LPAREN    : '(' ;
RPAREN    : ')' ;
LBRACK    : '[' ;
RBRACK    : ']' ;

HexLiteral
    : '0x' [0-9a-fA-F]+
    ;

// A number immediately followed by a unit name, with no space: `10m`, `3.5mps`, `1e2m`.
PhysicalLiteral
    : (FloatNumber | Digits) [a-zA-Z_]+
    ;

FloatLiteral
    : FloatNumber
    ;

IntLiteral
    : Digits
    ;

StringLiteral
    : '"' (~["\\\r\n] | '\\' .)* '"'
    | '\'' (~['\\\r\n] | '\\' .)* '\''
    ;

Identifier
    : [a-zA-Z_] [a-zA-Z0-9_]*
    ;

// One NEWLINE per logical line end; IndentingLexer measures the whitespace that follows it.
NEWLINE
    : ('\r'? '\n' | '\r') [ \t]*
    ;

LINE_JOIN
    : '\\' [ \t]* ('\r'? '\n' | '\r') -> skip
    ;

WS
    : [ \t]+ -> skip
    ;

COMMENT
    : '#' ~[\r\n]* -> skip
    ;

fragment Digits
    : [0-9]+
    ;

// Digits are required after the point so that `10..20` lexes as 10, .., 20.
fragment FloatNumber
    : Digits '.' Digits Exponent?
    | Digits Exponent
    ;

fragment Exponent
    : [eE] [+-]? Digits
    ;
