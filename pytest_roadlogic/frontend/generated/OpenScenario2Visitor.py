# Generated from OpenScenario2.g4 by ANTLR 4.13.2
from antlr4 import *
if "." in __name__:
    from .OpenScenario2Parser import OpenScenario2Parser
else:
    from OpenScenario2Parser import OpenScenario2Parser

# This class defines a complete generic visitor for a parse tree produced by OpenScenario2Parser.

class OpenScenario2Visitor(ParseTreeVisitor):

    # Visit a parse tree produced by OpenScenario2Parser#oscFile.
    def visitOscFile(self, ctx:OpenScenario2Parser.OscFileContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#importStatement.
    def visitImportStatement(self, ctx:OpenScenario2Parser.ImportStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#declaration.
    def visitDeclaration(self, ctx:OpenScenario2Parser.DeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#scenarioDeclaration.
    def visitScenarioDeclaration(self, ctx:OpenScenario2Parser.ScenarioDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#scenarioName.
    def visitScenarioName(self, ctx:OpenScenario2Parser.ScenarioNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#scenarioMember.
    def visitScenarioMember(self, ctx:OpenScenario2Parser.ScenarioMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#fieldDeclaration.
    def visitFieldDeclaration(self, ctx:OpenScenario2Parser.FieldDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#typeName.
    def visitTypeName(self, ctx:OpenScenario2Parser.TypeNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#doDirective.
    def visitDoDirective(self, ctx:OpenScenario2Parser.DoDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#behavior.
    def visitBehavior(self, ctx:OpenScenario2Parser.BehaviorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#composition.
    def visitComposition(self, ctx:OpenScenario2Parser.CompositionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#compositionOperator.
    def visitCompositionOperator(self, ctx:OpenScenario2Parser.CompositionOperatorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#invocation.
    def visitInvocation(self, ctx:OpenScenario2Parser.InvocationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#modifierInvocation.
    def visitModifierInvocation(self, ctx:OpenScenario2Parser.ModifierInvocationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#argumentList.
    def visitArgumentList(self, ctx:OpenScenario2Parser.ArgumentListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#argument.
    def visitArgument(self, ctx:OpenScenario2Parser.ArgumentContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#negation.
    def visitNegation(self, ctx:OpenScenario2Parser.NegationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#rangeExpression.
    def visitRangeExpression(self, ctx:OpenScenario2Parser.RangeExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#physicalExpression.
    def visitPhysicalExpression(self, ctx:OpenScenario2Parser.PhysicalExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#numberExpression.
    def visitNumberExpression(self, ctx:OpenScenario2Parser.NumberExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#stringExpression.
    def visitStringExpression(self, ctx:OpenScenario2Parser.StringExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#boolExpression.
    def visitBoolExpression(self, ctx:OpenScenario2Parser.BoolExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#nameExpression.
    def visitNameExpression(self, ctx:OpenScenario2Parser.NameExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#parenthesised.
    def visitParenthesised(self, ctx:OpenScenario2Parser.ParenthesisedContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#rangeLiteral.
    def visitRangeLiteral(self, ctx:OpenScenario2Parser.RangeLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#number.
    def visitNumber(self, ctx:OpenScenario2Parser.NumberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#dottedName.
    def visitDottedName(self, ctx:OpenScenario2Parser.DottedNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#identifier.
    def visitIdentifier(self, ctx:OpenScenario2Parser.IdentifierContext):
        return self.visitChildren(ctx)



del OpenScenario2Parser