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


    # Visit a parse tree produced by OpenScenario2Parser#behaviorName.
    def visitBehaviorName(self, ctx:OpenScenario2Parser.BehaviorNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#behaviorIdentifier.
    def visitBehaviorIdentifier(self, ctx:OpenScenario2Parser.BehaviorIdentifierContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#inheritance.
    def visitInheritance(self, ctx:OpenScenario2Parser.InheritanceContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#actorDeclaration.
    def visitActorDeclaration(self, ctx:OpenScenario2Parser.ActorDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#structDeclaration.
    def visitStructDeclaration(self, ctx:OpenScenario2Parser.StructDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#structMember.
    def visitStructMember(self, ctx:OpenScenario2Parser.StructMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#physicalTypeDeclaration.
    def visitPhysicalTypeDeclaration(self, ctx:OpenScenario2Parser.PhysicalTypeDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#unitDeclaration.
    def visitUnitDeclaration(self, ctx:OpenScenario2Parser.UnitDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#enumDeclaration.
    def visitEnumDeclaration(self, ctx:OpenScenario2Parser.EnumDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#enumMember.
    def visitEnumMember(self, ctx:OpenScenario2Parser.EnumMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#globalDeclaration.
    def visitGlobalDeclaration(self, ctx:OpenScenario2Parser.GlobalDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#extendDeclaration.
    def visitExtendDeclaration(self, ctx:OpenScenario2Parser.ExtendDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#extensionMember.
    def visitExtensionMember(self, ctx:OpenScenario2Parser.ExtensionMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#modifierDeclaration.
    def visitModifierDeclaration(self, ctx:OpenScenario2Parser.ModifierDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#namespaceStatement.
    def visitNamespaceStatement(self, ctx:OpenScenario2Parser.NamespaceStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#exportStatement.
    def visitExportStatement(self, ctx:OpenScenario2Parser.ExportStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#exportSpecification.
    def visitExportSpecification(self, ctx:OpenScenario2Parser.ExportSpecificationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#scenarioMember.
    def visitScenarioMember(self, ctx:OpenScenario2Parser.ScenarioMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#fieldDeclaration.
    def visitFieldDeclaration(self, ctx:OpenScenario2Parser.FieldDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#fieldConstraint.
    def visitFieldConstraint(self, ctx:OpenScenario2Parser.FieldConstraintContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#typeDeclarator.
    def visitTypeDeclarator(self, ctx:OpenScenario2Parser.TypeDeclaratorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#variableDeclaration.
    def visitVariableDeclaration(self, ctx:OpenScenario2Parser.VariableDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#sampleExpression.
    def visitSampleExpression(self, ctx:OpenScenario2Parser.SampleExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#keepConstraint.
    def visitKeepConstraint(self, ctx:OpenScenario2Parser.KeepConstraintContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#removeDefault.
    def visitRemoveDefault(self, ctx:OpenScenario2Parser.RemoveDefaultContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#eventDeclaration.
    def visitEventDeclaration(self, ctx:OpenScenario2Parser.EventDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#eventSpecification.
    def visitEventSpecification(self, ctx:OpenScenario2Parser.EventSpecificationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#methodDeclaration.
    def visitMethodDeclaration(self, ctx:OpenScenario2Parser.MethodDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#parameterList.
    def visitParameterList(self, ctx:OpenScenario2Parser.ParameterListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#parameter.
    def visitParameter(self, ctx:OpenScenario2Parser.ParameterContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#coverageDeclaration.
    def visitCoverageDeclaration(self, ctx:OpenScenario2Parser.CoverageDeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#onDirective.
    def visitOnDirective(self, ctx:OpenScenario2Parser.OnDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#doDirective.
    def visitDoDirective(self, ctx:OpenScenario2Parser.DoDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#doMember.
    def visitDoMember(self, ctx:OpenScenario2Parser.DoMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#composition.
    def visitComposition(self, ctx:OpenScenario2Parser.CompositionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#compositionOperator.
    def visitCompositionOperator(self, ctx:OpenScenario2Parser.CompositionOperatorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#behaviorInvocation.
    def visitBehaviorInvocation(self, ctx:OpenScenario2Parser.BehaviorInvocationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#behaviorWithMember.
    def visitBehaviorWithMember(self, ctx:OpenScenario2Parser.BehaviorWithMemberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#modifierInvocation.
    def visitModifierInvocation(self, ctx:OpenScenario2Parser.ModifierInvocationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#untilDirective.
    def visitUntilDirective(self, ctx:OpenScenario2Parser.UntilDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#waitDirective.
    def visitWaitDirective(self, ctx:OpenScenario2Parser.WaitDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#emitDirective.
    def visitEmitDirective(self, ctx:OpenScenario2Parser.EmitDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#callDirective.
    def visitCallDirective(self, ctx:OpenScenario2Parser.CallDirectiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#argumentList.
    def visitArgumentList(self, ctx:OpenScenario2Parser.ArgumentListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#argument.
    def visitArgument(self, ctx:OpenScenario2Parser.ArgumentContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#primaryExpression.
    def visitPrimaryExpression(self, ctx:OpenScenario2Parser.PrimaryExpressionContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#memberAccess.
    def visitMemberAccess(self, ctx:OpenScenario2Parser.MemberAccessContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#logicalNot.
    def visitLogicalNot(self, ctx:OpenScenario2Parser.LogicalNotContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#elementAccess.
    def visitElementAccess(self, ctx:OpenScenario2Parser.ElementAccessContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#conditional.
    def visitConditional(self, ctx:OpenScenario2Parser.ConditionalContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#logicalAnd.
    def visitLogicalAnd(self, ctx:OpenScenario2Parser.LogicalAndContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#unary.
    def visitUnary(self, ctx:OpenScenario2Parser.UnaryContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#multiplicative.
    def visitMultiplicative(self, ctx:OpenScenario2Parser.MultiplicativeContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#additive.
    def visitAdditive(self, ctx:OpenScenario2Parser.AdditiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#relation.
    def visitRelation(self, ctx:OpenScenario2Parser.RelationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#call.
    def visitCall(self, ctx:OpenScenario2Parser.CallContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#implication.
    def visitImplication(self, ctx:OpenScenario2Parser.ImplicationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#logicalOr.
    def visitLogicalOr(self, ctx:OpenScenario2Parser.LogicalOrContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#typeTest.
    def visitTypeTest(self, ctx:OpenScenario2Parser.TypeTestContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#physicalLiteral.
    def visitPhysicalLiteral(self, ctx:OpenScenario2Parser.PhysicalLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#numberLiteral.
    def visitNumberLiteral(self, ctx:OpenScenario2Parser.NumberLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#stringLiteral.
    def visitStringLiteral(self, ctx:OpenScenario2Parser.StringLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#boolLiteral.
    def visitBoolLiteral(self, ctx:OpenScenario2Parser.BoolLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#rangePrimary.
    def visitRangePrimary(self, ctx:OpenScenario2Parser.RangePrimaryContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#listLiteral.
    def visitListLiteral(self, ctx:OpenScenario2Parser.ListLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#enumValue.
    def visitEnumValue(self, ctx:OpenScenario2Parser.EnumValueContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#namePrimary.
    def visitNamePrimary(self, ctx:OpenScenario2Parser.NamePrimaryContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#parenthesised.
    def visitParenthesised(self, ctx:OpenScenario2Parser.ParenthesisedContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#rangeLiteral.
    def visitRangeLiteral(self, ctx:OpenScenario2Parser.RangeLiteralContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#dottedName.
    def visitDottedName(self, ctx:OpenScenario2Parser.DottedNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#identifier.
    def visitIdentifier(self, ctx:OpenScenario2Parser.IdentifierContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by OpenScenario2Parser#simpleIdentifier.
    def visitSimpleIdentifier(self, ctx:OpenScenario2Parser.SimpleIdentifierContext):
        return self.visitChildren(ctx)



del OpenScenario2Parser