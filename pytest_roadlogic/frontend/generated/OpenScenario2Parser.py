# Generated from OpenScenario2.g4 by ANTLR 4.13.2
# encoding: utf-8
from antlr4 import *
from io import StringIO
import sys
if sys.version_info[1] > 5:
	from typing import TextIO
else:
	from typing.io import TextIO

def serializedATN():
    return [
        4,1,31,233,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,1,0,5,0,44,8,0,10,0,12,0,47,9,0,1,0,5,0,50,8,0,10,0,12,0,53,
        9,0,1,0,1,0,5,0,57,8,0,10,0,12,0,60,9,0,1,0,1,0,1,1,1,1,1,1,3,1,
        67,8,1,1,1,1,1,1,2,1,2,1,3,1,3,1,3,1,3,1,3,1,3,4,3,79,8,3,11,3,12,
        3,80,1,3,1,3,1,4,1,4,1,4,3,4,88,8,4,1,4,1,4,1,5,1,5,3,5,94,8,5,1,
        6,1,6,1,6,5,6,99,8,6,10,6,12,6,102,9,6,1,6,1,6,1,6,1,6,3,6,108,8,
        6,1,6,1,6,1,7,1,7,1,8,1,8,1,8,1,9,1,9,1,9,3,9,120,8,9,1,9,1,9,3,
        9,124,8,9,1,10,1,10,1,10,3,10,129,8,10,1,10,3,10,132,8,10,1,10,1,
        10,1,10,1,10,4,10,138,8,10,11,10,12,10,139,1,10,1,10,1,11,1,11,1,
        12,1,12,1,12,3,12,149,8,12,1,12,1,12,1,12,3,12,154,8,12,1,12,1,12,
        1,12,1,12,1,12,1,12,4,12,162,8,12,11,12,12,12,163,1,12,1,12,1,12,
        3,12,169,8,12,1,13,1,13,1,13,3,13,174,8,13,1,13,1,13,1,13,3,13,179,
        8,13,1,13,1,13,1,13,1,14,1,14,1,14,5,14,187,8,14,10,14,12,14,190,
        9,14,1,15,1,15,1,15,3,15,195,8,15,1,15,1,15,1,16,1,16,1,16,1,16,
        1,16,1,16,1,16,1,16,1,16,1,16,1,16,1,16,3,16,211,8,16,1,17,1,17,
        1,17,1,17,1,17,1,17,3,17,219,8,17,1,18,1,18,1,19,1,19,1,19,5,19,
        226,8,19,10,19,12,19,229,9,19,1,20,1,20,1,20,0,0,21,0,2,4,6,8,10,
        12,14,16,18,20,22,24,26,28,30,32,34,36,38,40,0,3,1,0,4,6,1,0,8,9,
        2,0,20,20,22,23,243,0,45,1,0,0,0,2,63,1,0,0,0,4,70,1,0,0,0,6,72,
        1,0,0,0,8,87,1,0,0,0,10,93,1,0,0,0,12,95,1,0,0,0,14,111,1,0,0,0,
        16,113,1,0,0,0,18,119,1,0,0,0,20,125,1,0,0,0,22,143,1,0,0,0,24,148,
        1,0,0,0,26,173,1,0,0,0,28,183,1,0,0,0,30,194,1,0,0,0,32,210,1,0,
        0,0,34,212,1,0,0,0,36,220,1,0,0,0,38,222,1,0,0,0,40,230,1,0,0,0,
        42,44,5,26,0,0,43,42,1,0,0,0,44,47,1,0,0,0,45,43,1,0,0,0,45,46,1,
        0,0,0,46,51,1,0,0,0,47,45,1,0,0,0,48,50,3,2,1,0,49,48,1,0,0,0,50,
        53,1,0,0,0,51,49,1,0,0,0,51,52,1,0,0,0,52,58,1,0,0,0,53,51,1,0,0,
        0,54,57,3,4,2,0,55,57,5,26,0,0,56,54,1,0,0,0,56,55,1,0,0,0,57,60,
        1,0,0,0,58,56,1,0,0,0,58,59,1,0,0,0,59,61,1,0,0,0,60,58,1,0,0,0,
        61,62,5,0,0,1,62,1,1,0,0,0,63,66,5,1,0,0,64,67,5,24,0,0,65,67,3,
        38,19,0,66,64,1,0,0,0,66,65,1,0,0,0,67,68,1,0,0,0,68,69,5,26,0,0,
        69,3,1,0,0,0,70,71,3,6,3,0,71,5,1,0,0,0,72,73,5,2,0,0,73,74,3,8,
        4,0,74,75,5,13,0,0,75,76,5,26,0,0,76,78,5,30,0,0,77,79,3,10,5,0,
        78,77,1,0,0,0,79,80,1,0,0,0,80,78,1,0,0,0,80,81,1,0,0,0,81,82,1,
        0,0,0,82,83,5,31,0,0,83,7,1,0,0,0,84,85,3,40,20,0,85,86,5,11,0,0,
        86,88,1,0,0,0,87,84,1,0,0,0,87,88,1,0,0,0,88,89,1,0,0,0,89,90,3,
        40,20,0,90,9,1,0,0,0,91,94,3,12,6,0,92,94,3,16,8,0,93,91,1,0,0,0,
        93,92,1,0,0,0,94,11,1,0,0,0,95,100,3,40,20,0,96,97,5,12,0,0,97,99,
        3,40,20,0,98,96,1,0,0,0,99,102,1,0,0,0,100,98,1,0,0,0,100,101,1,
        0,0,0,101,103,1,0,0,0,102,100,1,0,0,0,103,104,5,13,0,0,104,107,3,
        14,7,0,105,106,5,14,0,0,106,108,3,32,16,0,107,105,1,0,0,0,107,108,
        1,0,0,0,108,109,1,0,0,0,109,110,5,26,0,0,110,13,1,0,0,0,111,112,
        3,40,20,0,112,15,1,0,0,0,113,114,5,3,0,0,114,115,3,18,9,0,115,17,
        1,0,0,0,116,117,3,40,20,0,117,118,5,13,0,0,118,120,1,0,0,0,119,116,
        1,0,0,0,119,120,1,0,0,0,120,123,1,0,0,0,121,124,3,20,10,0,122,124,
        3,24,12,0,123,121,1,0,0,0,123,122,1,0,0,0,124,19,1,0,0,0,125,131,
        3,22,11,0,126,128,5,16,0,0,127,129,3,28,14,0,128,127,1,0,0,0,128,
        129,1,0,0,0,129,130,1,0,0,0,130,132,5,17,0,0,131,126,1,0,0,0,131,
        132,1,0,0,0,132,133,1,0,0,0,133,134,5,13,0,0,134,135,5,26,0,0,135,
        137,5,30,0,0,136,138,3,18,9,0,137,136,1,0,0,0,138,139,1,0,0,0,139,
        137,1,0,0,0,139,140,1,0,0,0,140,141,1,0,0,0,141,142,5,31,0,0,142,
        21,1,0,0,0,143,144,7,0,0,0,144,23,1,0,0,0,145,146,3,40,20,0,146,
        147,5,11,0,0,147,149,1,0,0,0,148,145,1,0,0,0,148,149,1,0,0,0,149,
        150,1,0,0,0,150,151,3,40,20,0,151,153,5,16,0,0,152,154,3,28,14,0,
        153,152,1,0,0,0,153,154,1,0,0,0,154,155,1,0,0,0,155,168,5,17,0,0,
        156,157,5,7,0,0,157,158,5,13,0,0,158,159,5,26,0,0,159,161,5,30,0,
        0,160,162,3,26,13,0,161,160,1,0,0,0,162,163,1,0,0,0,163,161,1,0,
        0,0,163,164,1,0,0,0,164,165,1,0,0,0,165,166,5,31,0,0,166,169,1,0,
        0,0,167,169,5,26,0,0,168,156,1,0,0,0,168,167,1,0,0,0,169,25,1,0,
        0,0,170,171,3,40,20,0,171,172,5,11,0,0,172,174,1,0,0,0,173,170,1,
        0,0,0,173,174,1,0,0,0,174,175,1,0,0,0,175,176,3,40,20,0,176,178,
        5,16,0,0,177,179,3,28,14,0,178,177,1,0,0,0,178,179,1,0,0,0,179,180,
        1,0,0,0,180,181,5,17,0,0,181,182,5,26,0,0,182,27,1,0,0,0,183,188,
        3,30,15,0,184,185,5,12,0,0,185,187,3,30,15,0,186,184,1,0,0,0,187,
        190,1,0,0,0,188,186,1,0,0,0,188,189,1,0,0,0,189,29,1,0,0,0,190,188,
        1,0,0,0,191,192,3,40,20,0,192,193,5,13,0,0,193,195,1,0,0,0,194,191,
        1,0,0,0,194,195,1,0,0,0,195,196,1,0,0,0,196,197,3,32,16,0,197,31,
        1,0,0,0,198,199,5,15,0,0,199,211,3,32,16,0,200,211,3,34,17,0,201,
        211,5,21,0,0,202,211,3,36,18,0,203,211,5,24,0,0,204,211,7,1,0,0,
        205,211,3,38,19,0,206,207,5,16,0,0,207,208,3,32,16,0,208,209,5,17,
        0,0,209,211,1,0,0,0,210,198,1,0,0,0,210,200,1,0,0,0,210,201,1,0,
        0,0,210,202,1,0,0,0,210,203,1,0,0,0,210,204,1,0,0,0,210,205,1,0,
        0,0,210,206,1,0,0,0,211,33,1,0,0,0,212,213,5,18,0,0,213,214,3,32,
        16,0,214,215,5,10,0,0,215,216,3,32,16,0,216,218,5,19,0,0,217,219,
        3,40,20,0,218,217,1,0,0,0,218,219,1,0,0,0,219,35,1,0,0,0,220,221,
        7,2,0,0,221,37,1,0,0,0,222,227,3,40,20,0,223,224,5,11,0,0,224,226,
        3,40,20,0,225,223,1,0,0,0,226,229,1,0,0,0,227,225,1,0,0,0,227,228,
        1,0,0,0,228,39,1,0,0,0,229,227,1,0,0,0,230,231,5,25,0,0,231,41,1,
        0,0,0,26,45,51,56,58,66,80,87,93,100,107,119,123,128,131,139,148,
        153,163,168,173,178,188,194,210,218,227
    ]

class OpenScenario2Parser ( Parser ):

    grammarFileName = "OpenScenario2.g4"

    atn = ATNDeserializer().deserialize(serializedATN())

    decisionsToDFA = [ DFA(ds, i) for i, ds in enumerate(atn.decisionToState) ]

    sharedContextCache = PredictionContextCache()

    literalNames = [ "<INVALID>", "'import'", "'scenario'", "'do'", "'serial'", 
                     "'parallel'", "'one_of'", "'with'", "'true'", "'false'", 
                     "'..'", "'.'", "','", "':'", "'='", "'-'", "'('", "')'", 
                     "'['", "']'" ]

    symbolicNames = [ "<INVALID>", "IMPORT", "SCENARIO", "DO", "SERIAL", 
                      "PARALLEL", "ONE_OF", "WITH", "TRUE", "FALSE", "DOUBLEDOT", 
                      "DOT", "COMMA", "COLON", "ASSIGN", "MINUS", "LPAREN", 
                      "RPAREN", "LBRACK", "RBRACK", "HexLiteral", "PhysicalLiteral", 
                      "FloatLiteral", "IntLiteral", "StringLiteral", "Identifier", 
                      "NEWLINE", "LINE_JOIN", "WS", "COMMENT", "INDENT", 
                      "DEDENT" ]

    RULE_oscFile = 0
    RULE_importStatement = 1
    RULE_declaration = 2
    RULE_scenarioDeclaration = 3
    RULE_scenarioName = 4
    RULE_scenarioMember = 5
    RULE_fieldDeclaration = 6
    RULE_typeName = 7
    RULE_doDirective = 8
    RULE_behavior = 9
    RULE_composition = 10
    RULE_compositionOperator = 11
    RULE_invocation = 12
    RULE_modifierInvocation = 13
    RULE_argumentList = 14
    RULE_argument = 15
    RULE_expression = 16
    RULE_rangeLiteral = 17
    RULE_number = 18
    RULE_dottedName = 19
    RULE_identifier = 20

    ruleNames =  [ "oscFile", "importStatement", "declaration", "scenarioDeclaration", 
                   "scenarioName", "scenarioMember", "fieldDeclaration", 
                   "typeName", "doDirective", "behavior", "composition", 
                   "compositionOperator", "invocation", "modifierInvocation", 
                   "argumentList", "argument", "expression", "rangeLiteral", 
                   "number", "dottedName", "identifier" ]

    EOF = Token.EOF
    IMPORT=1
    SCENARIO=2
    DO=3
    SERIAL=4
    PARALLEL=5
    ONE_OF=6
    WITH=7
    TRUE=8
    FALSE=9
    DOUBLEDOT=10
    DOT=11
    COMMA=12
    COLON=13
    ASSIGN=14
    MINUS=15
    LPAREN=16
    RPAREN=17
    LBRACK=18
    RBRACK=19
    HexLiteral=20
    PhysicalLiteral=21
    FloatLiteral=22
    IntLiteral=23
    StringLiteral=24
    Identifier=25
    NEWLINE=26
    LINE_JOIN=27
    WS=28
    COMMENT=29
    INDENT=30
    DEDENT=31

    def __init__(self, input:TokenStream, output:TextIO = sys.stdout):
        super().__init__(input, output)
        self.checkVersion("4.13.2")
        self._interp = ParserATNSimulator(self, self.atn, self.decisionsToDFA, self.sharedContextCache)
        self._predicates = None




    class OscFileContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EOF(self):
            return self.getToken(OpenScenario2Parser.EOF, 0)

        def NEWLINE(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.NEWLINE)
            else:
                return self.getToken(OpenScenario2Parser.NEWLINE, i)

        def importStatement(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ImportStatementContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ImportStatementContext,i)


        def declaration(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.DeclarationContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.DeclarationContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_oscFile

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitOscFile" ):
                return visitor.visitOscFile(self)
            else:
                return visitor.visitChildren(self)




    def oscFile(self):

        localctx = OpenScenario2Parser.OscFileContext(self, self._ctx, self.state)
        self.enterRule(localctx, 0, self.RULE_oscFile)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 45
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,0,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 42
                    self.match(OpenScenario2Parser.NEWLINE) 
                self.state = 47
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,0,self._ctx)

            self.state = 51
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==1:
                self.state = 48
                self.importStatement()
                self.state = 53
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 58
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==2 or _la==26:
                self.state = 56
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [2]:
                    self.state = 54
                    self.declaration()
                    pass
                elif token in [26]:
                    self.state = 55
                    self.match(OpenScenario2Parser.NEWLINE)
                    pass
                else:
                    raise NoViableAltException(self)

                self.state = 60
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 61
            self.match(OpenScenario2Parser.EOF)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ImportStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def IMPORT(self):
            return self.getToken(OpenScenario2Parser.IMPORT, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def StringLiteral(self):
            return self.getToken(OpenScenario2Parser.StringLiteral, 0)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_importStatement

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitImportStatement" ):
                return visitor.visitImportStatement(self)
            else:
                return visitor.visitChildren(self)




    def importStatement(self):

        localctx = OpenScenario2Parser.ImportStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 2, self.RULE_importStatement)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 63
            self.match(OpenScenario2Parser.IMPORT)
            self.state = 66
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [24]:
                self.state = 64
                self.match(OpenScenario2Parser.StringLiteral)
                pass
            elif token in [25]:
                self.state = 65
                self.dottedName()
                pass
            else:
                raise NoViableAltException(self)

            self.state = 68
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def scenarioDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ScenarioDeclarationContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_declaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclaration" ):
                return visitor.visitDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def declaration(self):

        localctx = OpenScenario2Parser.DeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 4, self.RULE_declaration)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 70
            self.scenarioDeclaration()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ScenarioDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def SCENARIO(self):
            return self.getToken(OpenScenario2Parser.SCENARIO, 0)

        def scenarioName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ScenarioNameContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def scenarioMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ScenarioMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ScenarioMemberContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_scenarioDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitScenarioDeclaration" ):
                return visitor.visitScenarioDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def scenarioDeclaration(self):

        localctx = OpenScenario2Parser.ScenarioDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 6, self.RULE_scenarioDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 72
            self.match(OpenScenario2Parser.SCENARIO)
            self.state = 73
            self.scenarioName()
            self.state = 74
            self.match(OpenScenario2Parser.COLON)
            self.state = 75
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 76
            self.match(OpenScenario2Parser.INDENT)
            self.state = 78 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 77
                self.scenarioMember()
                self.state = 80 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not (_la==3 or _la==25):
                    break

            self.state = 82
            self.match(OpenScenario2Parser.DEDENT)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ScenarioNameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.actorType = None # IdentifierContext
            self.name = None # IdentifierContext

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def DOT(self):
            return self.getToken(OpenScenario2Parser.DOT, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_scenarioName

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitScenarioName" ):
                return visitor.visitScenarioName(self)
            else:
                return visitor.visitChildren(self)




    def scenarioName(self):

        localctx = OpenScenario2Parser.ScenarioNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 8, self.RULE_scenarioName)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 87
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,6,self._ctx)
            if la_ == 1:
                self.state = 84
                localctx.actorType = self.identifier()
                self.state = 85
                self.match(OpenScenario2Parser.DOT)


            self.state = 89
            localctx.name = self.identifier()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ScenarioMemberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def fieldDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.FieldDeclarationContext,0)


        def doDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DoDirectiveContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_scenarioMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitScenarioMember" ):
                return visitor.visitScenarioMember(self)
            else:
                return visitor.visitChildren(self)




    def scenarioMember(self):

        localctx = OpenScenario2Parser.ScenarioMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 10, self.RULE_scenarioMember)
        try:
            self.state = 93
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [25]:
                self.enterOuterAlt(localctx, 1)
                self.state = 91
                self.fieldDeclaration()
                pass
            elif token in [3]:
                self.enterOuterAlt(localctx, 2)
                self.state = 92
                self.doDirective()
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class FieldDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def typeName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeNameContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def ASSIGN(self):
            return self.getToken(OpenScenario2Parser.ASSIGN, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_fieldDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFieldDeclaration" ):
                return visitor.visitFieldDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def fieldDeclaration(self):

        localctx = OpenScenario2Parser.FieldDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 12, self.RULE_fieldDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 95
            self.identifier()
            self.state = 100
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==12:
                self.state = 96
                self.match(OpenScenario2Parser.COMMA)
                self.state = 97
                self.identifier()
                self.state = 102
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 103
            self.match(OpenScenario2Parser.COLON)
            self.state = 104
            self.typeName()
            self.state = 107
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==14:
                self.state = 105
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 106
                self.expression()


            self.state = 109
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class TypeNameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_typeName

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitTypeName" ):
                return visitor.visitTypeName(self)
            else:
                return visitor.visitChildren(self)




    def typeName(self):

        localctx = OpenScenario2Parser.TypeNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 14, self.RULE_typeName)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 111
            self.identifier()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DoDirectiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def DO(self):
            return self.getToken(OpenScenario2Parser.DO, 0)

        def behavior(self):
            return self.getTypedRuleContext(OpenScenario2Parser.BehaviorContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_doDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDoDirective" ):
                return visitor.visitDoDirective(self)
            else:
                return visitor.visitChildren(self)




    def doDirective(self):

        localctx = OpenScenario2Parser.DoDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 16, self.RULE_doDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 113
            self.match(OpenScenario2Parser.DO)
            self.state = 114
            self.behavior()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class BehaviorContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.label = None # IdentifierContext

        def composition(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CompositionContext,0)


        def invocation(self):
            return self.getTypedRuleContext(OpenScenario2Parser.InvocationContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_behavior

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitBehavior" ):
                return visitor.visitBehavior(self)
            else:
                return visitor.visitChildren(self)




    def behavior(self):

        localctx = OpenScenario2Parser.BehaviorContext(self, self._ctx, self.state)
        self.enterRule(localctx, 18, self.RULE_behavior)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 119
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,10,self._ctx)
            if la_ == 1:
                self.state = 116
                localctx.label = self.identifier()
                self.state = 117
                self.match(OpenScenario2Parser.COLON)


            self.state = 123
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [4, 5, 6]:
                self.state = 121
                self.composition()
                pass
            elif token in [25]:
                self.state = 122
                self.invocation()
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class CompositionContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def compositionOperator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CompositionOperatorContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def behavior(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.BehaviorContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.BehaviorContext,i)


        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_composition

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitComposition" ):
                return visitor.visitComposition(self)
            else:
                return visitor.visitChildren(self)




    def composition(self):

        localctx = OpenScenario2Parser.CompositionContext(self, self._ctx, self.state)
        self.enterRule(localctx, 20, self.RULE_composition)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 125
            self.compositionOperator()
            self.state = 131
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==16:
                self.state = 126
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 128
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 66421504) != 0):
                    self.state = 127
                    self.argumentList()


                self.state = 130
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 133
            self.match(OpenScenario2Parser.COLON)
            self.state = 134
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 135
            self.match(OpenScenario2Parser.INDENT)
            self.state = 137 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 136
                self.behavior()
                self.state = 139 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 33554544) != 0)):
                    break

            self.state = 141
            self.match(OpenScenario2Parser.DEDENT)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class CompositionOperatorContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def SERIAL(self):
            return self.getToken(OpenScenario2Parser.SERIAL, 0)

        def PARALLEL(self):
            return self.getToken(OpenScenario2Parser.PARALLEL, 0)

        def ONE_OF(self):
            return self.getToken(OpenScenario2Parser.ONE_OF, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_compositionOperator

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCompositionOperator" ):
                return visitor.visitCompositionOperator(self)
            else:
                return visitor.visitChildren(self)




    def compositionOperator(self):

        localctx = OpenScenario2Parser.CompositionOperatorContext(self, self._ctx, self.state)
        self.enterRule(localctx, 22, self.RULE_compositionOperator)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 143
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 112) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InvocationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.actor = None # IdentifierContext
            self.action = None # IdentifierContext

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def WITH(self):
            return self.getToken(OpenScenario2Parser.WITH, 0)

        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def DOT(self):
            return self.getToken(OpenScenario2Parser.DOT, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def modifierInvocation(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ModifierInvocationContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ModifierInvocationContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_invocation

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInvocation" ):
                return visitor.visitInvocation(self)
            else:
                return visitor.visitChildren(self)




    def invocation(self):

        localctx = OpenScenario2Parser.InvocationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 24, self.RULE_invocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 148
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,15,self._ctx)
            if la_ == 1:
                self.state = 145
                localctx.actor = self.identifier()
                self.state = 146
                self.match(OpenScenario2Parser.DOT)


            self.state = 150
            localctx.action = self.identifier()
            self.state = 151
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 153
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 66421504) != 0):
                self.state = 152
                self.argumentList()


            self.state = 155
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 168
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [7]:
                self.state = 156
                self.match(OpenScenario2Parser.WITH)
                self.state = 157
                self.match(OpenScenario2Parser.COLON)
                self.state = 158
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 159
                self.match(OpenScenario2Parser.INDENT)
                self.state = 161 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 160
                    self.modifierInvocation()
                    self.state = 163 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not (_la==25):
                        break

                self.state = 165
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [26]:
                self.state = 167
                self.match(OpenScenario2Parser.NEWLINE)
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ModifierInvocationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.actor = None # IdentifierContext
            self.name = None # IdentifierContext

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def DOT(self):
            return self.getToken(OpenScenario2Parser.DOT, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_modifierInvocation

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitModifierInvocation" ):
                return visitor.visitModifierInvocation(self)
            else:
                return visitor.visitChildren(self)




    def modifierInvocation(self):

        localctx = OpenScenario2Parser.ModifierInvocationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 26, self.RULE_modifierInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 173
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,19,self._ctx)
            if la_ == 1:
                self.state = 170
                localctx.actor = self.identifier()
                self.state = 171
                self.match(OpenScenario2Parser.DOT)


            self.state = 175
            localctx.name = self.identifier()
            self.state = 176
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 178
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 66421504) != 0):
                self.state = 177
                self.argumentList()


            self.state = 180
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 181
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ArgumentListContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def argument(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ArgumentContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ArgumentContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_argumentList

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitArgumentList" ):
                return visitor.visitArgumentList(self)
            else:
                return visitor.visitChildren(self)




    def argumentList(self):

        localctx = OpenScenario2Parser.ArgumentListContext(self, self._ctx, self.state)
        self.enterRule(localctx, 28, self.RULE_argumentList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 183
            self.argument()
            self.state = 188
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==12:
                self.state = 184
                self.match(OpenScenario2Parser.COMMA)
                self.state = 185
                self.argument()
                self.state = 190
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ArgumentContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.name = None # IdentifierContext

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_argument

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitArgument" ):
                return visitor.visitArgument(self)
            else:
                return visitor.visitChildren(self)




    def argument(self):

        localctx = OpenScenario2Parser.ArgumentContext(self, self._ctx, self.state)
        self.enterRule(localctx, 30, self.RULE_argument)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 194
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,22,self._ctx)
            if la_ == 1:
                self.state = 191
                localctx.name = self.identifier()
                self.state = 192
                self.match(OpenScenario2Parser.COLON)


            self.state = 196
            self.expression()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExpressionContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_expression

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class NegationContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def MINUS(self):
            return self.getToken(OpenScenario2Parser.MINUS, 0)
        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNegation" ):
                return visitor.visitNegation(self)
            else:
                return visitor.visitChildren(self)


    class StringExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def StringLiteral(self):
            return self.getToken(OpenScenario2Parser.StringLiteral, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStringExpression" ):
                return visitor.visitStringExpression(self)
            else:
                return visitor.visitChildren(self)


    class BoolExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def TRUE(self):
            return self.getToken(OpenScenario2Parser.TRUE, 0)
        def FALSE(self):
            return self.getToken(OpenScenario2Parser.FALSE, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitBoolExpression" ):
                return visitor.visitBoolExpression(self)
            else:
                return visitor.visitChildren(self)


    class NumberExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def number(self):
            return self.getTypedRuleContext(OpenScenario2Parser.NumberContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNumberExpression" ):
                return visitor.visitNumberExpression(self)
            else:
                return visitor.visitChildren(self)


    class RangeExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def rangeLiteral(self):
            return self.getTypedRuleContext(OpenScenario2Parser.RangeLiteralContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRangeExpression" ):
                return visitor.visitRangeExpression(self)
            else:
                return visitor.visitChildren(self)


    class PhysicalExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def PhysicalLiteral(self):
            return self.getToken(OpenScenario2Parser.PhysicalLiteral, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPhysicalExpression" ):
                return visitor.visitPhysicalExpression(self)
            else:
                return visitor.visitChildren(self)


    class NameExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNameExpression" ):
                return visitor.visitNameExpression(self)
            else:
                return visitor.visitChildren(self)


    class ParenthesisedContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)
        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitParenthesised" ):
                return visitor.visitParenthesised(self)
            else:
                return visitor.visitChildren(self)



    def expression(self):

        localctx = OpenScenario2Parser.ExpressionContext(self, self._ctx, self.state)
        self.enterRule(localctx, 32, self.RULE_expression)
        self._la = 0 # Token type
        try:
            self.state = 210
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [15]:
                localctx = OpenScenario2Parser.NegationContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 198
                self.match(OpenScenario2Parser.MINUS)
                self.state = 199
                self.expression()
                pass
            elif token in [18]:
                localctx = OpenScenario2Parser.RangeExpressionContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 200
                self.rangeLiteral()
                pass
            elif token in [21]:
                localctx = OpenScenario2Parser.PhysicalExpressionContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 201
                self.match(OpenScenario2Parser.PhysicalLiteral)
                pass
            elif token in [20, 22, 23]:
                localctx = OpenScenario2Parser.NumberExpressionContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 202
                self.number()
                pass
            elif token in [24]:
                localctx = OpenScenario2Parser.StringExpressionContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 203
                self.match(OpenScenario2Parser.StringLiteral)
                pass
            elif token in [8, 9]:
                localctx = OpenScenario2Parser.BoolExpressionContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 204
                _la = self._input.LA(1)
                if not(_la==8 or _la==9):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass
            elif token in [25]:
                localctx = OpenScenario2Parser.NameExpressionContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 205
                self.dottedName()
                pass
            elif token in [16]:
                localctx = OpenScenario2Parser.ParenthesisedContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 206
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 207
                self.expression()
                self.state = 208
                self.match(OpenScenario2Parser.RPAREN)
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class RangeLiteralContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.low = None # ExpressionContext
            self.high = None # ExpressionContext
            self.unit = None # IdentifierContext

        def LBRACK(self):
            return self.getToken(OpenScenario2Parser.LBRACK, 0)

        def DOUBLEDOT(self):
            return self.getToken(OpenScenario2Parser.DOUBLEDOT, 0)

        def RBRACK(self):
            return self.getToken(OpenScenario2Parser.RBRACK, 0)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)


        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_rangeLiteral

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRangeLiteral" ):
                return visitor.visitRangeLiteral(self)
            else:
                return visitor.visitChildren(self)




    def rangeLiteral(self):

        localctx = OpenScenario2Parser.RangeLiteralContext(self, self._ctx, self.state)
        self.enterRule(localctx, 34, self.RULE_rangeLiteral)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 212
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 213
            localctx.low = self.expression()
            self.state = 214
            self.match(OpenScenario2Parser.DOUBLEDOT)
            self.state = 215
            localctx.high = self.expression()
            self.state = 216
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 218
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==25:
                self.state = 217
                localctx.unit = self.identifier()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class NumberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def IntLiteral(self):
            return self.getToken(OpenScenario2Parser.IntLiteral, 0)

        def FloatLiteral(self):
            return self.getToken(OpenScenario2Parser.FloatLiteral, 0)

        def HexLiteral(self):
            return self.getToken(OpenScenario2Parser.HexLiteral, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_number

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNumber" ):
                return visitor.visitNumber(self)
            else:
                return visitor.visitChildren(self)




    def number(self):

        localctx = OpenScenario2Parser.NumberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 36, self.RULE_number)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 220
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 13631488) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DottedNameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def DOT(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.DOT)
            else:
                return self.getToken(OpenScenario2Parser.DOT, i)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_dottedName

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDottedName" ):
                return visitor.visitDottedName(self)
            else:
                return visitor.visitChildren(self)




    def dottedName(self):

        localctx = OpenScenario2Parser.DottedNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 38, self.RULE_dottedName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 222
            self.identifier()
            self.state = 227
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==11:
                self.state = 223
                self.match(OpenScenario2Parser.DOT)
                self.state = 224
                self.identifier()
                self.state = 229
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class IdentifierContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def Identifier(self):
            return self.getToken(OpenScenario2Parser.Identifier, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_identifier

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIdentifier" ):
                return visitor.visitIdentifier(self)
            else:
                return visitor.visitChildren(self)




    def identifier(self):

        localctx = OpenScenario2Parser.IdentifierContext(self, self._ctx, self.state)
        self.enterRule(localctx, 40, self.RULE_identifier)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 230
            self.match(OpenScenario2Parser.Identifier)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx





