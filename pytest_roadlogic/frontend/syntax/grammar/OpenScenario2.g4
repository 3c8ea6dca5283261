// Grammar of the ASAM OpenSCENARIO DSL that pytest-roadlogic reads.
//
// Written for this project from the language description in the standard (section 7.2) and
// docs/language.md (what the tool reads, for its users). It covers the syntax of ASAM OpenSCENARIO DSL 2.x: constructs the tool does
// not execute (on, call, cover/record, namespace/export, var and sample, external methods, type
// tests, user modifiers, the 2.1 namespace qualifier `ns::name`) parse here so that the checker can
// refuse them by name and place instead of a syntax error.
//
// The layout is Python-like: the lexer emits NEWLINE tokens, and
// pytest_roadlogic.frontend.syntax.lexer.IndentingLexer turns leading whitespace into the INDENT and
// DEDENT tokens declared below and drops line breaks inside (...) and [...]. Keeping that logic in
// Python (not in target-specific @members) keeps this file free of target code.
//
// The generated parser in ../generated is committed. Regenerate it with
//     python -m pytest_roadlogic.frontend.syntax.regenerate
// (tests/test_frontend_generated.py fails when it is stale).

grammar OpenScenario2;

tokens { INDENT, DEDENT }

// ---------------------------------------------------------------- files and declarations

// Imports belong before the declarations; the checker says so rather than the parser.
oscFile
    : (importStatement | declaration | NEWLINE)* EOF
    ;

importStatement
    : IMPORT (StringLiteral | dottedName) NEWLINE
    ;

declaration
    : scenarioDeclaration
    | physicalTypeDeclaration
    | unitDeclaration
    | actorDeclaration
    | structDeclaration
    | enumDeclaration
    | globalDeclaration
    | extendDeclaration
    | modifierDeclaration
    | namespaceStatement
    | exportStatement
    ;

// `scenario vehicle.overtake:` ties the scenario to an actor type; it is not a namespace.
// `action` declares a user behavior with the same members.
scenarioDeclaration
    : kind=(SCENARIO | ACTION) behaviorName inheritance? (COLON NEWLINE INDENT scenarioMember+ DEDENT | NEWLINE)
    ;

behaviorName
    : (actorType=identifier DOT)? name=behaviorIdentifier
    ;

// a behavior's own name may be a composition keyword (the standard's example `scenario vehicle.one_of:`)
behaviorIdentifier
    : identifier
    | SERIAL
    | PARALLEL
    | ONE_OF
    ;

inheritance
    : INHERITS parent=behaviorName (LPAREN condition=expression RPAREN)?
    ;

actorDeclaration
    : ACTOR identifier inheritance? (COLON NEWLINE INDENT structMember+ DEDENT | NEWLINE)
    ;

structDeclaration
    : STRUCT identifier inheritance? (COLON NEWLINE INDENT structMember+ DEDENT | NEWLINE)
    ;

structMember
    : fieldDeclaration
    | variableDeclaration
    | keepConstraint
    | removeDefault
    | eventDeclaration
    | methodDeclaration
    | coverageDeclaration
    ;

// `type velocity is SI(m: 1, s: -1)`: a physical type by its SI base-unit exponents.
physicalTypeDeclaration
    : TYPE name=identifier IS si=identifier LPAREN argumentList RPAREN NEWLINE
    ;

// `unit kph of velocity is SI(m: 1, s: -1, factor: 0.277777778)`.
unitDeclaration
    : UNIT name=identifier OF type=identifier IS si=identifier LPAREN argumentList RPAREN NEWLINE
    ;

enumDeclaration
    : ENUM identifier COLON LBRACK enumMember (COMMA enumMember)* COMMA? RBRACK NEWLINE
    ;

enumMember
    : identifier (ASSIGN (IntLiteral | HexLiteral))?
    ;

globalDeclaration
    : GLOBAL fieldDeclaration
    ;

// `extend s:` adds members to a scenario, actor or struct; `extend e: [a, b]` (or one member
// per line) adds members to an enum.
extendDeclaration
    : EXTEND behaviorName COLON NEWLINE INDENT extensionMember+ DEDENT
    | EXTEND behaviorName COLON LBRACK enumMember (COMMA enumMember)* COMMA? RBRACK NEWLINE
    ;

extensionMember
    : scenarioMember
    | enumMember NEWLINE
    ;

modifierDeclaration
    : MODIFIER behaviorName (OF identifier)? (COLON NEWLINE INDENT scenarioMember+ DEDENT | NEWLINE)
    ;

namespaceStatement
    : NAMESPACE identifier (USE identifier (COMMA identifier)*)? NEWLINE
    ;

exportStatement
    : EXPORT exportSpecification (COMMA exportSpecification)* NEWLINE
    ;

exportSpecification
    : dottedName
    | (simpleIdentifier? DOUBLECOLON)? STAR
    ;

// ---------------------------------------------------------------- members

scenarioMember
    : fieldDeclaration
    | variableDeclaration
    | keepConstraint
    | removeDefault
    | eventDeclaration
    | methodDeclaration
    | coverageDeclaration
    | onDirective
    | doDirective
    | modifierInvocation
    ;

// `v1, v2: car`, `gap: length = 10m`, `gap: length with: keep(it in [10..20]m)`.
fieldDeclaration
    : identifier (COMMA identifier)* COLON typeDeclarator (ASSIGN defaultValue=expression)?
      (WITH COLON (NEWLINE INDENT fieldConstraint+ DEDENT | fieldConstraint) | NEWLINE)
    ;

// `cover(...)`/`record(...)` inside a field's `with:` as public suites write them
fieldConstraint
    : keepConstraint
    | removeDefault
    | coverageDeclaration
    ;

typeDeclarator
    : LIST OF identifier
    | identifier
    ;

variableDeclaration
    : VAR identifier (COMMA identifier)* (COLON typeDeclarator)? (ASSIGN (sampleExpression | expression))? NEWLINE
    ;

// `sample(ego.speed, @overtake.start)`: a value taken when an event happens.
sampleExpression
    : SAMPLE LPAREN expression COMMA eventSpecification (COMMA expression)? RPAREN
    ;

keepConstraint
    : KEEP LPAREN strength=(DEFAULT | HARD)? expression RPAREN NEWLINE
    ;

removeDefault
    : REMOVE_DEFAULT LPAREN expression RPAREN NEWLINE
    ;

eventDeclaration
    : EVENT identifier (LPAREN parameterList? RPAREN)? (IS eventSpecification)? NEWLINE
    ;

// `@e`, `@e as x if cond`, or an expression such as `elapsed(3s)` or a boolean condition.
eventSpecification
    : AT_SIGN dottedName (AS alias=identifier)? (IF expression)?
    | expression
    ;

// `is expression e`, `is undefined`, `is external f()`, each optionally `is only ...`; a bare
// `is e` (without `expression`) is read too.
methodDeclaration
    : DEF identifier LPAREN parameterList? RPAREN (ARROW typeDeclarator)? IS ONLY? (EXPRESSION expression | UNDEFINED | EXTERNAL expression | expression) NEWLINE
    ;

parameterList
    : parameter (COMMA parameter)*
    ;

parameter
    : identifier COLON typeDeclarator (ASSIGN expression)?
    ;

coverageDeclaration
    : (COVER | RECORD) LPAREN argumentList? RPAREN NEWLINE
    ;

onDirective
    : ON eventSpecification COLON NEWLINE INDENT doMember+ DEDENT
    ;

doDirective
    : DO doMember
    ;

// ---------------------------------------------------------------- behavior

doMember
    : (label=identifier COLON)? (composition | behaviorInvocation | waitDirective | emitDirective | callDirective)
    ;

composition
    : compositionOperator (LPAREN argumentList? RPAREN)? COLON NEWLINE INDENT doMember+ DEDENT
    ;

compositionOperator
    : SERIAL
    | PARALLEL
    | ONE_OF
    ;

// `v1.drive()`, `v1.change_lane(side: left) with: ...`; the last name is the action.
behaviorInvocation
    : target=dottedName LPAREN argumentList? RPAREN
      (WITH COLON (NEWLINE INDENT behaviorWithMember+ DEDENT | behaviorWithMember) | NEWLINE)
    ;

behaviorWithMember
    : modifierInvocation
    | keepConstraint
    | removeDefault
    | untilDirective
    ;

// `lane(same_as: v2)`; labelled as the standard names a map modifier's results:
// `my_mod: map.roads_follow_in_junction(direction: right)`, then `my_mod.resulting_route`
modifierInvocation
    : (label=identifier COLON)? target=dottedName LPAREN argumentList? RPAREN NEWLINE
    ;

untilDirective
    : UNTIL eventSpecification NEWLINE
    ;

waitDirective
    : WAIT eventSpecification NEWLINE
    ;

emitDirective
    : EMIT identifier (LPAREN argumentList? RPAREN)? NEWLINE
    ;

callDirective
    : CALL expression NEWLINE
    ;

argumentList
    : argument (COMMA argument)* COMMA?
    ;

argument
    : (name=identifier COLON)? expression
    ;

// ---------------------------------------------------------------- expressions

// Alternatives are listed from the tightest binding to the loosest.
expression
    : expression DOT op=(IS | AS) LPAREN typeDeclarator RPAREN    # typeTest
    | expression DOT identifier                                   # memberAccess
    | expression LBRACK expression RBRACK                         # elementAccess
    | expression LPAREN argumentList? RPAREN                      # call
    | op=(MINUS | PLUS) expression                                # unary
    | expression op=(STAR | SLASH | PERCENT) expression           # multiplicative
    | expression op=(PLUS | MINUS) expression                     # additive
    | expression op=(EQ | NE | LT | LE | GT | GE | IN) expression # relation
    | NOT expression                                              # logicalNot
    | expression AND expression                                   # logicalAnd
    | expression OR expression                                    # logicalOr
    | <assoc=right> expression IMPLIES expression                 # implication
    | <assoc=right> expression QUESTION expression COLON expression # conditional
    | primary                                                     # primaryExpression
    ;

primary
    : PhysicalLiteral                                             # physicalLiteral
    | (IntLiteral | FloatLiteral | HexLiteral)                    # numberLiteral
    | StringLiteral                                               # stringLiteral
    | (TRUE | FALSE)                                              # boolLiteral
    | rangeLiteral                                                # rangePrimary
    | LBRACK (expression (COMMA expression)* COMMA?)? RBRACK      # listLiteral
    | enumType=identifier BANG member=identifier                  # enumValue
    | identifier                                                  # namePrimary
    | LPAREN expression RPAREN                                    # parenthesised
    ;

// `[10..20]m` (the paper's spelling, one unit after the range) and `[10m..20m]` (the standard's).
rangeLiteral
    : LBRACK low=expression DOUBLEDOT high=expression RBRACK unit=Identifier?
    ;

dottedName
    : identifier (DOT identifier)*
    ;

// Keywords that only start a construct in one place may still name things elsewhere, as the
// standard allows (`namespace: string` in a struct, a method called `sample`).
identifier
    : (qualifier=simpleIdentifier? DOUBLECOLON)? simpleIdentifier  // 2.1: `ns::name`, `::name` (the global namespace)
    ;

simpleIdentifier
    : Identifier
    | QuotedIdentifier
    | ACTION
    | MODIFIER
    | EVENT
    | HARD
    | LIST
    | OF
    | EXTERNAL
    | UNDEFINED
    | TYPE
    | UNIT
    | NAMESPACE
    | USE
    | EXPORT
    | GLOBAL
    | INHERITS
    | IMPORT
    | AS
    | ONLY
    | EXPRESSION
    | SAMPLE
    | ENUM
    | STRUCT
    | ACTOR
    | SCENARIO
    | EXTEND
    ;

// ---------------------------------------------------------------- lexer

IMPORT         : 'import' ;
SCENARIO       : 'scenario' ;
ACTION         : 'action' ;
ACTOR          : 'actor' ;
STRUCT         : 'struct' ;
ENUM           : 'enum' ;
TYPE           : 'type' ;
UNIT           : 'unit' ;
GLOBAL         : 'global' ;
EXTEND         : 'extend' ;
MODIFIER       : 'modifier' ;
NAMESPACE      : 'namespace' ;
USE            : 'use' ;
EXPORT         : 'export' ;
INHERITS       : 'inherits' ;
VAR            : 'var' ;
KEEP           : 'keep' ;
DEFAULT        : 'default' ;
HARD           : 'hard' ;
REMOVE_DEFAULT : 'remove_default' ;
EVENT          : 'event' ;
IS             : 'is' ;
IF             : 'if' ;
DEF            : 'def' ;
EXTERNAL       : 'external' ;
UNDEFINED      : 'undefined' ;
COVER          : 'cover' ;
RECORD         : 'record' ;
ON             : 'on' ;
DO             : 'do' ;
SERIAL         : 'serial' ;
PARALLEL       : 'parallel' ;
ONE_OF         : 'one_of' ;
WITH           : 'with' ;
UNTIL          : 'until' ;
WAIT           : 'wait' ;
EMIT           : 'emit' ;
CALL           : 'call' ;
LIST           : 'list' ;
OF             : 'of' ;
IN             : 'in' ;
AND            : 'and' ;
OR             : 'or' ;
NOT            : 'not' ;
TRUE           : 'true' ;
FALSE          : 'false' ;
AS             : 'as' ;
ONLY           : 'only' ;
EXPRESSION     : 'expression' ;
SAMPLE         : 'sample' ;

DOUBLEDOT : '..' ;
DOT       : '.' ;
COMMA     : ',' ;
DOUBLECOLON : '::' ;
COLON     : ':' ;
ARROW     : '->' ;
IMPLIES   : '=>' ;
EQ        : '==' ;
NE        : '!=' ;
LE        : '<=' ;
GE        : '>=' ;
LT        : '<' ;
GT        : '>' ;
ASSIGN    : '=' ;
BANG      : '!' ;
QUESTION  : '?' ;
AT_SIGN   : '@' ;
PLUS      : '+' ;
MINUS     : '-' ;
STAR      : '*' ;
SLASH     : '/' ;
PERCENT   : '%' ;
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
    : '"""' .*? '"""'
    | '\'\'\'' .*? '\'\'\''
    | '"' (~["\\\r\n] | '\\' .)* '"'
    | '\'' (~['\\\r\n] | '\\' .)* '\''
    ;

Identifier
    : [a-zA-Z_] [a-zA-Z0-9_]*
    ;

// `|any name|` names something that is not a valid identifier.
QuotedIdentifier
    : '|' ~[|\r\n]+ '|'
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

// Digits are required after the point so that `10..20` lexes as 10, .., 20; `.5` and `.1e+7`
// (no digit before the point) are numbers too.
fragment FloatNumber
    : Digits '.' Digits Exponent?
    | '.' Digits Exponent?
    | Digits Exponent
    ;

fragment Exponent
    : [eE] [+-]? Digits
    ;
