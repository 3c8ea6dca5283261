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
        4,1,81,654,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,2,43,7,43,2,44,7,44,2,45,7,45,2,46,
        7,46,2,47,7,47,1,0,1,0,1,0,5,0,100,8,0,10,0,12,0,103,9,0,1,0,1,0,
        1,1,1,1,1,1,3,1,110,8,1,1,1,1,1,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,
        1,2,3,2,123,8,2,1,3,1,3,1,3,3,3,128,8,3,1,3,1,3,1,3,1,3,4,3,134,
        8,3,11,3,12,3,135,1,3,1,3,1,3,3,3,141,8,3,1,4,1,4,1,4,3,4,146,8,
        4,1,4,1,4,1,5,1,5,1,5,1,5,1,5,1,5,3,5,156,8,5,1,6,1,6,1,6,3,6,161,
        8,6,1,6,1,6,1,6,1,6,4,6,167,8,6,11,6,12,6,168,1,6,1,6,1,6,3,6,174,
        8,6,1,7,1,7,1,7,3,7,179,8,7,1,7,1,7,1,7,1,7,4,7,185,8,7,11,7,12,
        7,186,1,7,1,7,1,7,3,7,192,8,7,1,8,1,8,1,8,1,8,1,8,1,8,3,8,200,8,
        8,1,9,1,9,1,9,1,9,1,9,1,9,1,9,5,9,209,8,9,10,9,12,9,212,9,9,1,9,
        3,9,215,8,9,1,9,1,9,1,9,1,10,1,10,1,10,3,10,223,8,10,1,11,1,11,1,
        11,1,12,1,12,1,12,1,12,1,12,1,12,4,12,234,8,12,11,12,12,12,235,1,
        12,1,12,1,13,1,13,1,13,1,13,3,13,244,8,13,1,13,1,13,1,13,1,13,4,
        13,250,8,13,11,13,12,13,251,1,13,1,13,1,13,3,13,257,8,13,1,14,1,
        14,1,14,1,14,1,14,1,14,5,14,265,8,14,10,14,12,14,268,9,14,3,14,270,
        8,14,1,14,1,14,1,15,1,15,1,15,1,15,5,15,278,8,15,10,15,12,15,281,
        9,15,1,15,1,15,1,16,1,16,1,16,1,16,1,16,1,16,1,16,1,16,1,16,1,16,
        3,16,295,8,16,1,17,1,17,1,17,5,17,300,8,17,10,17,12,17,303,9,17,
        1,17,1,17,1,17,1,17,3,17,309,8,17,1,17,1,17,1,17,1,17,1,17,4,17,
        316,8,17,11,17,12,17,317,1,17,1,17,1,17,3,17,323,8,17,1,17,3,17,
        326,8,17,1,18,1,18,3,18,330,8,18,1,19,1,19,1,19,1,19,3,19,336,8,
        19,1,20,1,20,1,20,1,20,5,20,342,8,20,10,20,12,20,345,9,20,1,20,1,
        20,3,20,349,8,20,1,20,1,20,3,20,353,8,20,1,20,1,20,1,21,1,21,1,21,
        3,21,360,8,21,1,21,1,21,1,21,1,21,1,22,1,22,1,22,1,22,1,22,1,22,
        1,23,1,23,1,23,1,23,3,23,376,8,23,1,23,3,23,379,8,23,1,23,1,23,3,
        23,383,8,23,1,23,1,23,1,24,1,24,1,24,1,24,3,24,391,8,24,1,24,3,24,
        394,8,24,1,25,1,25,1,25,1,25,3,25,400,8,25,1,25,1,25,1,25,3,25,405,
        8,25,1,25,1,25,3,25,409,8,25,1,25,1,25,3,25,413,8,25,1,25,1,25,1,
        26,1,26,1,26,5,26,420,8,26,10,26,12,26,423,9,26,1,27,1,27,1,27,1,
        27,1,27,3,27,430,8,27,1,28,1,28,1,28,3,28,435,8,28,1,28,1,28,1,28,
        1,29,1,29,1,29,1,29,1,29,1,29,4,29,446,8,29,11,29,12,29,447,1,29,
        1,29,1,30,1,30,1,30,1,31,1,31,1,31,3,31,458,8,31,1,31,1,31,1,31,
        1,31,1,31,3,31,465,8,31,1,32,1,32,1,32,3,32,470,8,32,1,32,3,32,473,
        8,32,1,32,1,32,1,32,1,32,4,32,479,8,32,11,32,12,32,480,1,32,1,32,
        1,33,1,33,1,34,1,34,1,34,3,34,490,8,34,1,34,1,34,1,34,1,34,1,34,
        1,34,4,34,498,8,34,11,34,12,34,499,1,34,1,34,1,34,3,34,505,8,34,
        1,34,3,34,508,8,34,1,35,1,35,1,35,1,35,3,35,514,8,35,1,36,1,36,1,
        36,3,36,519,8,36,1,36,1,36,1,36,1,37,1,37,1,37,1,37,1,38,1,38,1,
        38,1,38,1,39,1,39,1,39,1,39,3,39,536,8,39,1,39,3,39,539,8,39,1,39,
        1,39,1,40,1,40,1,40,1,40,1,41,1,41,1,41,5,41,550,8,41,10,41,12,41,
        553,9,41,1,41,3,41,556,8,41,1,42,1,42,1,42,3,42,561,8,42,1,42,1,
        42,1,43,1,43,1,43,1,43,1,43,1,43,3,43,571,8,43,1,43,1,43,1,43,1,
        43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,1,
        43,1,43,1,43,1,43,1,43,1,43,1,43,1,43,3,43,597,8,43,1,43,5,43,600,
        8,43,10,43,12,43,603,9,43,1,44,1,44,1,44,1,44,1,44,1,44,1,44,1,44,
        1,44,5,44,614,8,44,10,44,12,44,617,9,44,1,44,3,44,620,8,44,3,44,
        622,8,44,1,44,1,44,1,44,1,44,1,44,1,44,1,44,1,44,1,44,1,44,3,44,
        634,8,44,1,45,1,45,1,45,1,45,1,45,1,45,3,45,642,8,45,1,46,1,46,1,
        46,5,46,647,8,46,10,46,12,46,650,9,46,1,47,1,47,1,47,0,1,86,48,0,
        2,4,6,8,10,12,14,16,18,20,22,24,26,28,30,32,34,36,38,40,42,44,46,
        48,50,52,54,56,58,60,62,64,66,68,70,72,74,76,78,80,82,84,86,88,90,
        92,94,0,11,1,0,2,3,2,0,69,69,72,72,1,0,16,17,1,0,25,26,1,0,29,31,
        1,0,60,61,1,0,62,64,2,0,39,39,51,56,2,0,69,69,71,72,1,0,43,44,7,
        0,3,3,9,9,17,17,19,19,23,24,37,38,74,75,721,0,101,1,0,0,0,2,106,
        1,0,0,0,4,122,1,0,0,0,6,124,1,0,0,0,8,145,1,0,0,0,10,149,1,0,0,0,
        12,157,1,0,0,0,14,175,1,0,0,0,16,199,1,0,0,0,18,201,1,0,0,0,20,219,
        1,0,0,0,22,224,1,0,0,0,24,227,1,0,0,0,26,239,1,0,0,0,28,258,1,0,
        0,0,30,273,1,0,0,0,32,294,1,0,0,0,34,296,1,0,0,0,36,329,1,0,0,0,
        38,335,1,0,0,0,40,337,1,0,0,0,42,356,1,0,0,0,44,365,1,0,0,0,46,371,
        1,0,0,0,48,393,1,0,0,0,50,395,1,0,0,0,52,416,1,0,0,0,54,424,1,0,
        0,0,56,431,1,0,0,0,58,439,1,0,0,0,60,451,1,0,0,0,62,457,1,0,0,0,
        64,466,1,0,0,0,66,484,1,0,0,0,68,486,1,0,0,0,70,513,1,0,0,0,72,515,
        1,0,0,0,74,523,1,0,0,0,76,527,1,0,0,0,78,531,1,0,0,0,80,542,1,0,
        0,0,82,546,1,0,0,0,84,560,1,0,0,0,86,570,1,0,0,0,88,633,1,0,0,0,
        90,635,1,0,0,0,92,643,1,0,0,0,94,651,1,0,0,0,96,100,3,2,1,0,97,100,
        3,4,2,0,98,100,5,76,0,0,99,96,1,0,0,0,99,97,1,0,0,0,99,98,1,0,0,
        0,100,103,1,0,0,0,101,99,1,0,0,0,101,102,1,0,0,0,102,104,1,0,0,0,
        103,101,1,0,0,0,104,105,5,0,0,1,105,1,1,0,0,0,106,109,5,1,0,0,107,
        110,5,73,0,0,108,110,3,92,46,0,109,107,1,0,0,0,109,108,1,0,0,0,110,
        111,1,0,0,0,111,112,5,76,0,0,112,3,1,0,0,0,113,123,3,6,3,0,114,123,
        3,12,6,0,115,123,3,14,7,0,116,123,3,18,9,0,117,123,3,22,11,0,118,
        123,3,24,12,0,119,123,3,26,13,0,120,123,3,28,14,0,121,123,3,30,15,
        0,122,113,1,0,0,0,122,114,1,0,0,0,122,115,1,0,0,0,122,116,1,0,0,
        0,122,117,1,0,0,0,122,118,1,0,0,0,122,119,1,0,0,0,122,120,1,0,0,
        0,122,121,1,0,0,0,123,5,1,0,0,0,124,125,7,0,0,0,125,127,3,8,4,0,
        126,128,3,10,5,0,127,126,1,0,0,0,127,128,1,0,0,0,128,140,1,0,0,0,
        129,130,5,48,0,0,130,131,5,76,0,0,131,133,5,80,0,0,132,134,3,32,
        16,0,133,132,1,0,0,0,134,135,1,0,0,0,135,133,1,0,0,0,135,136,1,0,
        0,0,136,137,1,0,0,0,137,138,5,81,0,0,138,141,1,0,0,0,139,141,5,76,
        0,0,140,129,1,0,0,0,140,139,1,0,0,0,141,7,1,0,0,0,142,143,3,94,47,
        0,143,144,5,46,0,0,144,146,1,0,0,0,145,142,1,0,0,0,145,146,1,0,0,
        0,146,147,1,0,0,0,147,148,3,94,47,0,148,9,1,0,0,0,149,150,5,13,0,
        0,150,155,3,8,4,0,151,152,5,65,0,0,152,153,3,86,43,0,153,154,5,66,
        0,0,154,156,1,0,0,0,155,151,1,0,0,0,155,156,1,0,0,0,156,11,1,0,0,
        0,157,158,5,4,0,0,158,160,3,94,47,0,159,161,3,10,5,0,160,159,1,0,
        0,0,160,161,1,0,0,0,161,173,1,0,0,0,162,163,5,48,0,0,163,164,5,76,
        0,0,164,166,5,80,0,0,165,167,3,16,8,0,166,165,1,0,0,0,167,168,1,
        0,0,0,168,166,1,0,0,0,168,169,1,0,0,0,169,170,1,0,0,0,170,171,5,
        81,0,0,171,174,1,0,0,0,172,174,5,76,0,0,173,162,1,0,0,0,173,172,
        1,0,0,0,174,13,1,0,0,0,175,176,5,5,0,0,176,178,3,94,47,0,177,179,
        3,10,5,0,178,177,1,0,0,0,178,179,1,0,0,0,179,191,1,0,0,0,180,181,
        5,48,0,0,181,182,5,76,0,0,182,184,5,80,0,0,183,185,3,16,8,0,184,
        183,1,0,0,0,185,186,1,0,0,0,186,184,1,0,0,0,186,187,1,0,0,0,187,
        188,1,0,0,0,188,189,5,81,0,0,189,192,1,0,0,0,190,192,5,76,0,0,191,
        180,1,0,0,0,191,190,1,0,0,0,192,15,1,0,0,0,193,200,3,34,17,0,194,
        200,3,42,21,0,195,200,3,44,22,0,196,200,3,46,23,0,197,200,3,50,25,
        0,198,200,3,56,28,0,199,193,1,0,0,0,199,194,1,0,0,0,199,195,1,0,
        0,0,199,196,1,0,0,0,199,197,1,0,0,0,199,198,1,0,0,0,200,17,1,0,0,
        0,201,202,5,6,0,0,202,203,3,94,47,0,203,204,5,48,0,0,204,205,5,67,
        0,0,205,210,3,20,10,0,206,207,5,47,0,0,207,209,3,20,10,0,208,206,
        1,0,0,0,209,212,1,0,0,0,210,208,1,0,0,0,210,211,1,0,0,0,211,214,
        1,0,0,0,212,210,1,0,0,0,213,215,5,47,0,0,214,213,1,0,0,0,214,215,
        1,0,0,0,215,216,1,0,0,0,216,217,5,68,0,0,217,218,5,76,0,0,218,19,
        1,0,0,0,219,222,3,94,47,0,220,221,5,57,0,0,221,223,7,1,0,0,222,220,
        1,0,0,0,222,223,1,0,0,0,223,21,1,0,0,0,224,225,5,7,0,0,225,226,3,
        34,17,0,226,23,1,0,0,0,227,228,5,8,0,0,228,229,3,8,4,0,229,230,5,
        48,0,0,230,231,5,76,0,0,231,233,5,80,0,0,232,234,3,32,16,0,233,232,
        1,0,0,0,234,235,1,0,0,0,235,233,1,0,0,0,235,236,1,0,0,0,236,237,
        1,0,0,0,237,238,5,81,0,0,238,25,1,0,0,0,239,240,5,9,0,0,240,243,
        3,8,4,0,241,242,5,38,0,0,242,244,3,94,47,0,243,241,1,0,0,0,243,244,
        1,0,0,0,244,256,1,0,0,0,245,246,5,48,0,0,246,247,5,76,0,0,247,249,
        5,80,0,0,248,250,3,32,16,0,249,248,1,0,0,0,250,251,1,0,0,0,251,249,
        1,0,0,0,251,252,1,0,0,0,252,253,1,0,0,0,253,254,5,81,0,0,254,257,
        1,0,0,0,255,257,5,76,0,0,256,245,1,0,0,0,256,255,1,0,0,0,257,27,
        1,0,0,0,258,259,5,10,0,0,259,269,3,94,47,0,260,261,5,11,0,0,261,
        266,3,94,47,0,262,263,5,47,0,0,263,265,3,94,47,0,264,262,1,0,0,0,
        265,268,1,0,0,0,266,264,1,0,0,0,266,267,1,0,0,0,267,270,1,0,0,0,
        268,266,1,0,0,0,269,260,1,0,0,0,269,270,1,0,0,0,270,271,1,0,0,0,
        271,272,5,76,0,0,272,29,1,0,0,0,273,274,5,12,0,0,274,279,3,92,46,
        0,275,276,5,47,0,0,276,278,3,92,46,0,277,275,1,0,0,0,278,281,1,0,
        0,0,279,277,1,0,0,0,279,280,1,0,0,0,280,282,1,0,0,0,281,279,1,0,
        0,0,282,283,5,76,0,0,283,31,1,0,0,0,284,295,3,34,17,0,285,295,3,
        40,20,0,286,295,3,42,21,0,287,295,3,44,22,0,288,295,3,46,23,0,289,
        295,3,50,25,0,290,295,3,56,28,0,291,295,3,58,29,0,292,295,3,60,30,
        0,293,295,3,72,36,0,294,284,1,0,0,0,294,285,1,0,0,0,294,286,1,0,
        0,0,294,287,1,0,0,0,294,288,1,0,0,0,294,289,1,0,0,0,294,290,1,0,
        0,0,294,291,1,0,0,0,294,292,1,0,0,0,294,293,1,0,0,0,295,33,1,0,0,
        0,296,301,3,94,47,0,297,298,5,47,0,0,298,300,3,94,47,0,299,297,1,
        0,0,0,300,303,1,0,0,0,301,299,1,0,0,0,301,302,1,0,0,0,302,304,1,
        0,0,0,303,301,1,0,0,0,304,305,5,48,0,0,305,308,3,38,19,0,306,307,
        5,57,0,0,307,309,3,86,43,0,308,306,1,0,0,0,308,309,1,0,0,0,309,325,
        1,0,0,0,310,311,5,32,0,0,311,322,5,48,0,0,312,313,5,76,0,0,313,315,
        5,80,0,0,314,316,3,36,18,0,315,314,1,0,0,0,316,317,1,0,0,0,317,315,
        1,0,0,0,317,318,1,0,0,0,318,319,1,0,0,0,319,320,5,81,0,0,320,323,
        1,0,0,0,321,323,3,36,18,0,322,312,1,0,0,0,322,321,1,0,0,0,323,326,
        1,0,0,0,324,326,5,76,0,0,325,310,1,0,0,0,325,324,1,0,0,0,326,35,
        1,0,0,0,327,330,3,42,21,0,328,330,3,44,22,0,329,327,1,0,0,0,329,
        328,1,0,0,0,330,37,1,0,0,0,331,332,5,37,0,0,332,333,5,38,0,0,333,
        336,3,94,47,0,334,336,3,94,47,0,335,331,1,0,0,0,335,334,1,0,0,0,
        336,39,1,0,0,0,337,338,5,14,0,0,338,343,3,94,47,0,339,340,5,47,0,
        0,340,342,3,94,47,0,341,339,1,0,0,0,342,345,1,0,0,0,343,341,1,0,
        0,0,343,344,1,0,0,0,344,348,1,0,0,0,345,343,1,0,0,0,346,347,5,48,
        0,0,347,349,3,38,19,0,348,346,1,0,0,0,348,349,1,0,0,0,349,352,1,
        0,0,0,350,351,5,57,0,0,351,353,3,86,43,0,352,350,1,0,0,0,352,353,
        1,0,0,0,353,354,1,0,0,0,354,355,5,76,0,0,355,41,1,0,0,0,356,357,
        5,15,0,0,357,359,5,65,0,0,358,360,7,2,0,0,359,358,1,0,0,0,359,360,
        1,0,0,0,360,361,1,0,0,0,361,362,3,86,43,0,362,363,5,66,0,0,363,364,
        5,76,0,0,364,43,1,0,0,0,365,366,5,18,0,0,366,367,5,65,0,0,367,368,
        3,86,43,0,368,369,5,66,0,0,369,370,5,76,0,0,370,45,1,0,0,0,371,372,
        5,19,0,0,372,378,3,94,47,0,373,375,5,65,0,0,374,376,3,52,26,0,375,
        374,1,0,0,0,375,376,1,0,0,0,376,377,1,0,0,0,377,379,5,66,0,0,378,
        373,1,0,0,0,378,379,1,0,0,0,379,382,1,0,0,0,380,381,5,20,0,0,381,
        383,3,48,24,0,382,380,1,0,0,0,382,383,1,0,0,0,383,384,1,0,0,0,384,
        385,5,76,0,0,385,47,1,0,0,0,386,387,5,59,0,0,387,390,3,92,46,0,388,
        389,5,21,0,0,389,391,3,86,43,0,390,388,1,0,0,0,390,391,1,0,0,0,391,
        394,1,0,0,0,392,394,3,86,43,0,393,386,1,0,0,0,393,392,1,0,0,0,394,
        49,1,0,0,0,395,396,5,22,0,0,396,397,3,94,47,0,397,399,5,65,0,0,398,
        400,3,52,26,0,399,398,1,0,0,0,399,400,1,0,0,0,400,401,1,0,0,0,401,
        404,5,66,0,0,402,403,5,49,0,0,403,405,3,38,19,0,404,402,1,0,0,0,
        404,405,1,0,0,0,405,406,1,0,0,0,406,412,5,20,0,0,407,409,5,23,0,
        0,408,407,1,0,0,0,408,409,1,0,0,0,409,410,1,0,0,0,410,413,3,86,43,
        0,411,413,5,24,0,0,412,408,1,0,0,0,412,411,1,0,0,0,413,414,1,0,0,
        0,414,415,5,76,0,0,415,51,1,0,0,0,416,421,3,54,27,0,417,418,5,47,
        0,0,418,420,3,54,27,0,419,417,1,0,0,0,420,423,1,0,0,0,421,419,1,
        0,0,0,421,422,1,0,0,0,422,53,1,0,0,0,423,421,1,0,0,0,424,425,3,94,
        47,0,425,426,5,48,0,0,426,429,3,38,19,0,427,428,5,57,0,0,428,430,
        3,86,43,0,429,427,1,0,0,0,429,430,1,0,0,0,430,55,1,0,0,0,431,432,
        7,3,0,0,432,434,5,65,0,0,433,435,3,82,41,0,434,433,1,0,0,0,434,435,
        1,0,0,0,435,436,1,0,0,0,436,437,5,66,0,0,437,438,5,76,0,0,438,57,
        1,0,0,0,439,440,5,27,0,0,440,441,3,48,24,0,441,442,5,48,0,0,442,
        443,5,76,0,0,443,445,5,80,0,0,444,446,3,62,31,0,445,444,1,0,0,0,
        446,447,1,0,0,0,447,445,1,0,0,0,447,448,1,0,0,0,448,449,1,0,0,0,
        449,450,5,81,0,0,450,59,1,0,0,0,451,452,5,28,0,0,452,453,3,62,31,
        0,453,61,1,0,0,0,454,455,3,94,47,0,455,456,5,48,0,0,456,458,1,0,
        0,0,457,454,1,0,0,0,457,458,1,0,0,0,458,464,1,0,0,0,459,465,3,64,
        32,0,460,465,3,68,34,0,461,465,3,76,38,0,462,465,3,78,39,0,463,465,
        3,80,40,0,464,459,1,0,0,0,464,460,1,0,0,0,464,461,1,0,0,0,464,462,
        1,0,0,0,464,463,1,0,0,0,465,63,1,0,0,0,466,472,3,66,33,0,467,469,
        5,65,0,0,468,470,3,82,41,0,469,468,1,0,0,0,469,470,1,0,0,0,470,471,
        1,0,0,0,471,473,5,66,0,0,472,467,1,0,0,0,472,473,1,0,0,0,473,474,
        1,0,0,0,474,475,5,48,0,0,475,476,5,76,0,0,476,478,5,80,0,0,477,479,
        3,62,31,0,478,477,1,0,0,0,479,480,1,0,0,0,480,478,1,0,0,0,480,481,
        1,0,0,0,481,482,1,0,0,0,482,483,5,81,0,0,483,65,1,0,0,0,484,485,
        7,4,0,0,485,67,1,0,0,0,486,487,3,92,46,0,487,489,5,65,0,0,488,490,
        3,82,41,0,489,488,1,0,0,0,489,490,1,0,0,0,490,491,1,0,0,0,491,507,
        5,66,0,0,492,493,5,32,0,0,493,504,5,48,0,0,494,495,5,76,0,0,495,
        497,5,80,0,0,496,498,3,70,35,0,497,496,1,0,0,0,498,499,1,0,0,0,499,
        497,1,0,0,0,499,500,1,0,0,0,500,501,1,0,0,0,501,502,5,81,0,0,502,
        505,1,0,0,0,503,505,3,70,35,0,504,494,1,0,0,0,504,503,1,0,0,0,505,
        508,1,0,0,0,506,508,5,76,0,0,507,492,1,0,0,0,507,506,1,0,0,0,508,
        69,1,0,0,0,509,514,3,72,36,0,510,514,3,42,21,0,511,514,3,44,22,0,
        512,514,3,74,37,0,513,509,1,0,0,0,513,510,1,0,0,0,513,511,1,0,0,
        0,513,512,1,0,0,0,514,71,1,0,0,0,515,516,3,92,46,0,516,518,5,65,
        0,0,517,519,3,82,41,0,518,517,1,0,0,0,518,519,1,0,0,0,519,520,1,
        0,0,0,520,521,5,66,0,0,521,522,5,76,0,0,522,73,1,0,0,0,523,524,5,
        33,0,0,524,525,3,48,24,0,525,526,5,76,0,0,526,75,1,0,0,0,527,528,
        5,34,0,0,528,529,3,48,24,0,529,530,5,76,0,0,530,77,1,0,0,0,531,532,
        5,35,0,0,532,538,3,94,47,0,533,535,5,65,0,0,534,536,3,82,41,0,535,
        534,1,0,0,0,535,536,1,0,0,0,536,537,1,0,0,0,537,539,5,66,0,0,538,
        533,1,0,0,0,538,539,1,0,0,0,539,540,1,0,0,0,540,541,5,76,0,0,541,
        79,1,0,0,0,542,543,5,36,0,0,543,544,3,86,43,0,544,545,5,76,0,0,545,
        81,1,0,0,0,546,551,3,84,42,0,547,548,5,47,0,0,548,550,3,84,42,0,
        549,547,1,0,0,0,550,553,1,0,0,0,551,549,1,0,0,0,551,552,1,0,0,0,
        552,555,1,0,0,0,553,551,1,0,0,0,554,556,5,47,0,0,555,554,1,0,0,0,
        555,556,1,0,0,0,556,83,1,0,0,0,557,558,3,94,47,0,558,559,5,48,0,
        0,559,561,1,0,0,0,560,557,1,0,0,0,560,561,1,0,0,0,561,562,1,0,0,
        0,562,563,3,86,43,0,563,85,1,0,0,0,564,565,6,43,-1,0,565,566,7,5,
        0,0,566,571,3,86,43,9,567,568,5,42,0,0,568,571,3,86,43,5,569,571,
        3,88,44,0,570,564,1,0,0,0,570,567,1,0,0,0,570,569,1,0,0,0,571,601,
        1,0,0,0,572,573,10,8,0,0,573,574,7,6,0,0,574,600,3,86,43,9,575,576,
        10,7,0,0,576,577,7,5,0,0,577,600,3,86,43,8,578,579,10,6,0,0,579,
        580,7,7,0,0,580,600,3,86,43,7,581,582,10,4,0,0,582,583,5,40,0,0,
        583,600,3,86,43,5,584,585,10,3,0,0,585,586,5,41,0,0,586,600,3,86,
        43,4,587,588,10,2,0,0,588,589,5,50,0,0,589,600,3,86,43,2,590,591,
        10,11,0,0,591,592,5,46,0,0,592,600,3,94,47,0,593,594,10,10,0,0,594,
        596,5,65,0,0,595,597,3,82,41,0,596,595,1,0,0,0,596,597,1,0,0,0,597,
        598,1,0,0,0,598,600,5,66,0,0,599,572,1,0,0,0,599,575,1,0,0,0,599,
        578,1,0,0,0,599,581,1,0,0,0,599,584,1,0,0,0,599,587,1,0,0,0,599,
        590,1,0,0,0,599,593,1,0,0,0,600,603,1,0,0,0,601,599,1,0,0,0,601,
        602,1,0,0,0,602,87,1,0,0,0,603,601,1,0,0,0,604,634,5,70,0,0,605,
        634,7,8,0,0,606,634,5,73,0,0,607,634,7,9,0,0,608,634,3,90,45,0,609,
        621,5,67,0,0,610,615,3,86,43,0,611,612,5,47,0,0,612,614,3,86,43,
        0,613,611,1,0,0,0,614,617,1,0,0,0,615,613,1,0,0,0,615,616,1,0,0,
        0,616,619,1,0,0,0,617,615,1,0,0,0,618,620,5,47,0,0,619,618,1,0,0,
        0,619,620,1,0,0,0,620,622,1,0,0,0,621,610,1,0,0,0,621,622,1,0,0,
        0,622,623,1,0,0,0,623,634,5,68,0,0,624,625,3,94,47,0,625,626,5,58,
        0,0,626,627,3,94,47,0,627,634,1,0,0,0,628,634,3,94,47,0,629,630,
        5,65,0,0,630,631,3,86,43,0,631,632,5,66,0,0,632,634,1,0,0,0,633,
        604,1,0,0,0,633,605,1,0,0,0,633,606,1,0,0,0,633,607,1,0,0,0,633,
        608,1,0,0,0,633,609,1,0,0,0,633,624,1,0,0,0,633,628,1,0,0,0,633,
        629,1,0,0,0,634,89,1,0,0,0,635,636,5,67,0,0,636,637,3,86,43,0,637,
        638,5,45,0,0,638,639,3,86,43,0,639,641,5,68,0,0,640,642,5,74,0,0,
        641,640,1,0,0,0,641,642,1,0,0,0,642,91,1,0,0,0,643,648,3,94,47,0,
        644,645,5,46,0,0,645,647,3,94,47,0,646,644,1,0,0,0,647,650,1,0,0,
        0,648,646,1,0,0,0,648,649,1,0,0,0,649,93,1,0,0,0,650,648,1,0,0,0,
        651,652,7,10,0,0,652,95,1,0,0,0,77,99,101,109,122,127,135,140,145,
        155,160,168,173,178,186,191,199,210,214,222,235,243,251,256,266,
        269,279,294,301,308,317,322,325,329,335,343,348,352,359,375,378,
        382,390,393,399,404,408,412,421,429,434,447,457,464,469,472,480,
        489,499,504,507,513,518,535,538,551,555,560,570,596,599,601,615,
        619,621,633,641,648
    ]

class OpenScenario2Parser ( Parser ):

    grammarFileName = "OpenScenario2.g4"

    atn = ATNDeserializer().deserialize(serializedATN())

    decisionsToDFA = [ DFA(ds, i) for i, ds in enumerate(atn.decisionToState) ]

    sharedContextCache = PredictionContextCache()

    literalNames = [ "<INVALID>", "'import'", "'scenario'", "'action'", 
                     "'actor'", "'struct'", "'enum'", "'global'", "'extend'", 
                     "'modifier'", "'namespace'", "'use'", "'export'", "'inherits'", 
                     "'var'", "'keep'", "'default'", "'hard'", "'remove_default'", 
                     "'event'", "'is'", "'if'", "'def'", "'external'", "'undefined'", 
                     "'cover'", "'record'", "'on'", "'do'", "'serial'", 
                     "'parallel'", "'one_of'", "'with'", "'until'", "'wait'", 
                     "'emit'", "'call'", "'list'", "'of'", "'in'", "'and'", 
                     "'or'", "'not'", "'true'", "'false'", "'..'", "'.'", 
                     "','", "':'", "'->'", "'=>'", "'=='", "'!='", "'<='", 
                     "'>='", "'<'", "'>'", "'='", "'!'", "'@'", "'+'", "'-'", 
                     "'*'", "'/'", "'%'", "'('", "')'", "'['", "']'" ]

    symbolicNames = [ "<INVALID>", "IMPORT", "SCENARIO", "ACTION", "ACTOR", 
                      "STRUCT", "ENUM", "GLOBAL", "EXTEND", "MODIFIER", 
                      "NAMESPACE", "USE", "EXPORT", "INHERITS", "VAR", "KEEP", 
                      "DEFAULT", "HARD", "REMOVE_DEFAULT", "EVENT", "IS", 
                      "IF", "DEF", "EXTERNAL", "UNDEFINED", "COVER", "RECORD", 
                      "ON", "DO", "SERIAL", "PARALLEL", "ONE_OF", "WITH", 
                      "UNTIL", "WAIT", "EMIT", "CALL", "LIST", "OF", "IN", 
                      "AND", "OR", "NOT", "TRUE", "FALSE", "DOUBLEDOT", 
                      "DOT", "COMMA", "COLON", "ARROW", "IMPLIES", "EQ", 
                      "NE", "LE", "GE", "LT", "GT", "ASSIGN", "BANG", "AT_SIGN", 
                      "PLUS", "MINUS", "STAR", "SLASH", "PERCENT", "LPAREN", 
                      "RPAREN", "LBRACK", "RBRACK", "HexLiteral", "PhysicalLiteral", 
                      "FloatLiteral", "IntLiteral", "StringLiteral", "Identifier", 
                      "QuotedIdentifier", "NEWLINE", "LINE_JOIN", "WS", 
                      "COMMENT", "INDENT", "DEDENT" ]

    RULE_oscFile = 0
    RULE_importStatement = 1
    RULE_declaration = 2
    RULE_scenarioDeclaration = 3
    RULE_behaviorName = 4
    RULE_inheritance = 5
    RULE_actorDeclaration = 6
    RULE_structDeclaration = 7
    RULE_structMember = 8
    RULE_enumDeclaration = 9
    RULE_enumMember = 10
    RULE_globalDeclaration = 11
    RULE_extendDeclaration = 12
    RULE_modifierDeclaration = 13
    RULE_namespaceStatement = 14
    RULE_exportStatement = 15
    RULE_scenarioMember = 16
    RULE_fieldDeclaration = 17
    RULE_fieldConstraint = 18
    RULE_typeDeclarator = 19
    RULE_variableDeclaration = 20
    RULE_keepConstraint = 21
    RULE_removeDefault = 22
    RULE_eventDeclaration = 23
    RULE_eventSpecification = 24
    RULE_methodDeclaration = 25
    RULE_parameterList = 26
    RULE_parameter = 27
    RULE_coverageDeclaration = 28
    RULE_onDirective = 29
    RULE_doDirective = 30
    RULE_doMember = 31
    RULE_composition = 32
    RULE_compositionOperator = 33
    RULE_behaviorInvocation = 34
    RULE_behaviorWithMember = 35
    RULE_modifierInvocation = 36
    RULE_untilDirective = 37
    RULE_waitDirective = 38
    RULE_emitDirective = 39
    RULE_callDirective = 40
    RULE_argumentList = 41
    RULE_argument = 42
    RULE_expression = 43
    RULE_primary = 44
    RULE_rangeLiteral = 45
    RULE_dottedName = 46
    RULE_identifier = 47

    ruleNames =  [ "oscFile", "importStatement", "declaration", "scenarioDeclaration", 
                   "behaviorName", "inheritance", "actorDeclaration", "structDeclaration", 
                   "structMember", "enumDeclaration", "enumMember", "globalDeclaration", 
                   "extendDeclaration", "modifierDeclaration", "namespaceStatement", 
                   "exportStatement", "scenarioMember", "fieldDeclaration", 
                   "fieldConstraint", "typeDeclarator", "variableDeclaration", 
                   "keepConstraint", "removeDefault", "eventDeclaration", 
                   "eventSpecification", "methodDeclaration", "parameterList", 
                   "parameter", "coverageDeclaration", "onDirective", "doDirective", 
                   "doMember", "composition", "compositionOperator", "behaviorInvocation", 
                   "behaviorWithMember", "modifierInvocation", "untilDirective", 
                   "waitDirective", "emitDirective", "callDirective", "argumentList", 
                   "argument", "expression", "primary", "rangeLiteral", 
                   "dottedName", "identifier" ]

    EOF = Token.EOF
    IMPORT=1
    SCENARIO=2
    ACTION=3
    ACTOR=4
    STRUCT=5
    ENUM=6
    GLOBAL=7
    EXTEND=8
    MODIFIER=9
    NAMESPACE=10
    USE=11
    EXPORT=12
    INHERITS=13
    VAR=14
    KEEP=15
    DEFAULT=16
    HARD=17
    REMOVE_DEFAULT=18
    EVENT=19
    IS=20
    IF=21
    DEF=22
    EXTERNAL=23
    UNDEFINED=24
    COVER=25
    RECORD=26
    ON=27
    DO=28
    SERIAL=29
    PARALLEL=30
    ONE_OF=31
    WITH=32
    UNTIL=33
    WAIT=34
    EMIT=35
    CALL=36
    LIST=37
    OF=38
    IN=39
    AND=40
    OR=41
    NOT=42
    TRUE=43
    FALSE=44
    DOUBLEDOT=45
    DOT=46
    COMMA=47
    COLON=48
    ARROW=49
    IMPLIES=50
    EQ=51
    NE=52
    LE=53
    GE=54
    LT=55
    GT=56
    ASSIGN=57
    BANG=58
    AT_SIGN=59
    PLUS=60
    MINUS=61
    STAR=62
    SLASH=63
    PERCENT=64
    LPAREN=65
    RPAREN=66
    LBRACK=67
    RBRACK=68
    HexLiteral=69
    PhysicalLiteral=70
    FloatLiteral=71
    IntLiteral=72
    StringLiteral=73
    Identifier=74
    QuotedIdentifier=75
    NEWLINE=76
    LINE_JOIN=77
    WS=78
    COMMENT=79
    INDENT=80
    DEDENT=81

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


        def NEWLINE(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.NEWLINE)
            else:
                return self.getToken(OpenScenario2Parser.NEWLINE, i)

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
            self.state = 101
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while (((_la) & ~0x3f) == 0 and ((1 << _la) & 6142) != 0) or _la==76:
                self.state = 99
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [1]:
                    self.state = 96
                    self.importStatement()
                    pass
                elif token in [2, 3, 4, 5, 6, 7, 8, 9, 10, 12]:
                    self.state = 97
                    self.declaration()
                    pass
                elif token in [76]:
                    self.state = 98
                    self.match(OpenScenario2Parser.NEWLINE)
                    pass
                else:
                    raise NoViableAltException(self)

                self.state = 103
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 104
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
            self.state = 106
            self.match(OpenScenario2Parser.IMPORT)
            self.state = 109
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [73]:
                self.state = 107
                self.match(OpenScenario2Parser.StringLiteral)
                pass
            elif token in [3, 9, 17, 19, 23, 24, 37, 38, 74, 75]:
                self.state = 108
                self.dottedName()
                pass
            else:
                raise NoViableAltException(self)

            self.state = 111
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


        def actorDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ActorDeclarationContext,0)


        def structDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.StructDeclarationContext,0)


        def enumDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EnumDeclarationContext,0)


        def globalDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.GlobalDeclarationContext,0)


        def extendDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExtendDeclarationContext,0)


        def modifierDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ModifierDeclarationContext,0)


        def namespaceStatement(self):
            return self.getTypedRuleContext(OpenScenario2Parser.NamespaceStatementContext,0)


        def exportStatement(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExportStatementContext,0)


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
            self.state = 122
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [2, 3]:
                self.enterOuterAlt(localctx, 1)
                self.state = 113
                self.scenarioDeclaration()
                pass
            elif token in [4]:
                self.enterOuterAlt(localctx, 2)
                self.state = 114
                self.actorDeclaration()
                pass
            elif token in [5]:
                self.enterOuterAlt(localctx, 3)
                self.state = 115
                self.structDeclaration()
                pass
            elif token in [6]:
                self.enterOuterAlt(localctx, 4)
                self.state = 116
                self.enumDeclaration()
                pass
            elif token in [7]:
                self.enterOuterAlt(localctx, 5)
                self.state = 117
                self.globalDeclaration()
                pass
            elif token in [8]:
                self.enterOuterAlt(localctx, 6)
                self.state = 118
                self.extendDeclaration()
                pass
            elif token in [9]:
                self.enterOuterAlt(localctx, 7)
                self.state = 119
                self.modifierDeclaration()
                pass
            elif token in [10]:
                self.enterOuterAlt(localctx, 8)
                self.state = 120
                self.namespaceStatement()
                pass
            elif token in [12]:
                self.enterOuterAlt(localctx, 9)
                self.state = 121
                self.exportStatement()
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


    class ScenarioDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.kind = None # Token

        def behaviorName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.BehaviorNameContext,0)


        def SCENARIO(self):
            return self.getToken(OpenScenario2Parser.SCENARIO, 0)

        def ACTION(self):
            return self.getToken(OpenScenario2Parser.ACTION, 0)

        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def inheritance(self):
            return self.getTypedRuleContext(OpenScenario2Parser.InheritanceContext,0)


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
            self.state = 124
            localctx.kind = self._input.LT(1)
            _la = self._input.LA(1)
            if not(_la==2 or _la==3):
                localctx.kind = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 125
            self.behaviorName()
            self.state = 127
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==13:
                self.state = 126
                self.inheritance()


            self.state = 140
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [48]:
                self.state = 129
                self.match(OpenScenario2Parser.COLON)
                self.state = 130
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 131
                self.match(OpenScenario2Parser.INDENT)
                self.state = 133 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 132
                    self.scenarioMember()
                    self.state = 135 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 412850504200) != 0) or _la==74 or _la==75):
                        break

                self.state = 137
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [76]:
                self.state = 139
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


    class BehaviorNameContext(ParserRuleContext):
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
            return OpenScenario2Parser.RULE_behaviorName

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitBehaviorName" ):
                return visitor.visitBehaviorName(self)
            else:
                return visitor.visitChildren(self)




    def behaviorName(self):

        localctx = OpenScenario2Parser.BehaviorNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 8, self.RULE_behaviorName)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 145
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,7,self._ctx)
            if la_ == 1:
                self.state = 142
                localctx.actorType = self.identifier()
                self.state = 143
                self.match(OpenScenario2Parser.DOT)


            self.state = 147
            localctx.name = self.identifier()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InheritanceContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.parent = None # BehaviorNameContext
            self.condition = None # ExpressionContext

        def INHERITS(self):
            return self.getToken(OpenScenario2Parser.INHERITS, 0)

        def behaviorName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.BehaviorNameContext,0)


        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_inheritance

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInheritance" ):
                return visitor.visitInheritance(self)
            else:
                return visitor.visitChildren(self)




    def inheritance(self):

        localctx = OpenScenario2Parser.InheritanceContext(self, self._ctx, self.state)
        self.enterRule(localctx, 10, self.RULE_inheritance)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 149
            self.match(OpenScenario2Parser.INHERITS)
            self.state = 150
            localctx.parent = self.behaviorName()
            self.state = 155
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==65:
                self.state = 151
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 152
                localctx.condition = self.expression(0)
                self.state = 153
                self.match(OpenScenario2Parser.RPAREN)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ActorDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ACTOR(self):
            return self.getToken(OpenScenario2Parser.ACTOR, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def inheritance(self):
            return self.getTypedRuleContext(OpenScenario2Parser.InheritanceContext,0)


        def structMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.StructMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.StructMemberContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_actorDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitActorDeclaration" ):
                return visitor.visitActorDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def actorDeclaration(self):

        localctx = OpenScenario2Parser.ActorDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 12, self.RULE_actorDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 157
            self.match(OpenScenario2Parser.ACTOR)
            self.state = 158
            self.identifier()
            self.state = 160
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==13:
                self.state = 159
                self.inheritance()


            self.state = 173
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [48]:
                self.state = 162
                self.match(OpenScenario2Parser.COLON)
                self.state = 163
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 164
                self.match(OpenScenario2Parser.INDENT)
                self.state = 166 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 165
                    self.structMember()
                    self.state = 168 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 412447834632) != 0) or _la==74 or _la==75):
                        break

                self.state = 170
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [76]:
                self.state = 172
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


    class StructDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def STRUCT(self):
            return self.getToken(OpenScenario2Parser.STRUCT, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def inheritance(self):
            return self.getTypedRuleContext(OpenScenario2Parser.InheritanceContext,0)


        def structMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.StructMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.StructMemberContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_structDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStructDeclaration" ):
                return visitor.visitStructDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def structDeclaration(self):

        localctx = OpenScenario2Parser.StructDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 14, self.RULE_structDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 175
            self.match(OpenScenario2Parser.STRUCT)
            self.state = 176
            self.identifier()
            self.state = 178
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==13:
                self.state = 177
                self.inheritance()


            self.state = 191
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [48]:
                self.state = 180
                self.match(OpenScenario2Parser.COLON)
                self.state = 181
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 182
                self.match(OpenScenario2Parser.INDENT)
                self.state = 184 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 183
                    self.structMember()
                    self.state = 186 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 412447834632) != 0) or _la==74 or _la==75):
                        break

                self.state = 188
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [76]:
                self.state = 190
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


    class StructMemberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def fieldDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.FieldDeclarationContext,0)


        def keepConstraint(self):
            return self.getTypedRuleContext(OpenScenario2Parser.KeepConstraintContext,0)


        def removeDefault(self):
            return self.getTypedRuleContext(OpenScenario2Parser.RemoveDefaultContext,0)


        def eventDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventDeclarationContext,0)


        def methodDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.MethodDeclarationContext,0)


        def coverageDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CoverageDeclarationContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_structMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStructMember" ):
                return visitor.visitStructMember(self)
            else:
                return visitor.visitChildren(self)




    def structMember(self):

        localctx = OpenScenario2Parser.StructMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 16, self.RULE_structMember)
        try:
            self.state = 199
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,15,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 193
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 194
                self.keepConstraint()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 195
                self.removeDefault()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 196
                self.eventDeclaration()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 197
                self.methodDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 198
                self.coverageDeclaration()
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class EnumDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ENUM(self):
            return self.getToken(OpenScenario2Parser.ENUM, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def LBRACK(self):
            return self.getToken(OpenScenario2Parser.LBRACK, 0)

        def enumMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.EnumMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.EnumMemberContext,i)


        def RBRACK(self):
            return self.getToken(OpenScenario2Parser.RBRACK, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_enumDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEnumDeclaration" ):
                return visitor.visitEnumDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def enumDeclaration(self):

        localctx = OpenScenario2Parser.EnumDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 18, self.RULE_enumDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 201
            self.match(OpenScenario2Parser.ENUM)
            self.state = 202
            self.identifier()
            self.state = 203
            self.match(OpenScenario2Parser.COLON)
            self.state = 204
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 205
            self.enumMember()
            self.state = 210
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,16,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 206
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 207
                    self.enumMember() 
                self.state = 212
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,16,self._ctx)

            self.state = 214
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==47:
                self.state = 213
                self.match(OpenScenario2Parser.COMMA)


            self.state = 216
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 217
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class EnumMemberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def ASSIGN(self):
            return self.getToken(OpenScenario2Parser.ASSIGN, 0)

        def IntLiteral(self):
            return self.getToken(OpenScenario2Parser.IntLiteral, 0)

        def HexLiteral(self):
            return self.getToken(OpenScenario2Parser.HexLiteral, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_enumMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEnumMember" ):
                return visitor.visitEnumMember(self)
            else:
                return visitor.visitChildren(self)




    def enumMember(self):

        localctx = OpenScenario2Parser.EnumMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 20, self.RULE_enumMember)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 219
            self.identifier()
            self.state = 222
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==57:
                self.state = 220
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 221
                _la = self._input.LA(1)
                if not(_la==69 or _la==72):
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


    class GlobalDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def GLOBAL(self):
            return self.getToken(OpenScenario2Parser.GLOBAL, 0)

        def fieldDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.FieldDeclarationContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_globalDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitGlobalDeclaration" ):
                return visitor.visitGlobalDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def globalDeclaration(self):

        localctx = OpenScenario2Parser.GlobalDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 22, self.RULE_globalDeclaration)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 224
            self.match(OpenScenario2Parser.GLOBAL)
            self.state = 225
            self.fieldDeclaration()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExtendDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EXTEND(self):
            return self.getToken(OpenScenario2Parser.EXTEND, 0)

        def behaviorName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.BehaviorNameContext,0)


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
            return OpenScenario2Parser.RULE_extendDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExtendDeclaration" ):
                return visitor.visitExtendDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def extendDeclaration(self):

        localctx = OpenScenario2Parser.ExtendDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 24, self.RULE_extendDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 227
            self.match(OpenScenario2Parser.EXTEND)
            self.state = 228
            self.behaviorName()
            self.state = 229
            self.match(OpenScenario2Parser.COLON)
            self.state = 230
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 231
            self.match(OpenScenario2Parser.INDENT)
            self.state = 233 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 232
                self.scenarioMember()
                self.state = 235 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 412850504200) != 0) or _la==74 or _la==75):
                    break

            self.state = 237
            self.match(OpenScenario2Parser.DEDENT)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ModifierDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def MODIFIER(self):
            return self.getToken(OpenScenario2Parser.MODIFIER, 0)

        def behaviorName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.BehaviorNameContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def OF(self):
            return self.getToken(OpenScenario2Parser.OF, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def scenarioMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ScenarioMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ScenarioMemberContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_modifierDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitModifierDeclaration" ):
                return visitor.visitModifierDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def modifierDeclaration(self):

        localctx = OpenScenario2Parser.ModifierDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 26, self.RULE_modifierDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 239
            self.match(OpenScenario2Parser.MODIFIER)
            self.state = 240
            self.behaviorName()
            self.state = 243
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==38:
                self.state = 241
                self.match(OpenScenario2Parser.OF)
                self.state = 242
                self.identifier()


            self.state = 256
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [48]:
                self.state = 245
                self.match(OpenScenario2Parser.COLON)
                self.state = 246
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 247
                self.match(OpenScenario2Parser.INDENT)
                self.state = 249 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 248
                    self.scenarioMember()
                    self.state = 251 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 412850504200) != 0) or _la==74 or _la==75):
                        break

                self.state = 253
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [76]:
                self.state = 255
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


    class NamespaceStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def NAMESPACE(self):
            return self.getToken(OpenScenario2Parser.NAMESPACE, 0)

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def USE(self):
            return self.getToken(OpenScenario2Parser.USE, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_namespaceStatement

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNamespaceStatement" ):
                return visitor.visitNamespaceStatement(self)
            else:
                return visitor.visitChildren(self)




    def namespaceStatement(self):

        localctx = OpenScenario2Parser.NamespaceStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 28, self.RULE_namespaceStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 258
            self.match(OpenScenario2Parser.NAMESPACE)
            self.state = 259
            self.identifier()
            self.state = 269
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==11:
                self.state = 260
                self.match(OpenScenario2Parser.USE)
                self.state = 261
                self.identifier()
                self.state = 266
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==47:
                    self.state = 262
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 263
                    self.identifier()
                    self.state = 268
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)



            self.state = 271
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExportStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EXPORT(self):
            return self.getToken(OpenScenario2Parser.EXPORT, 0)

        def dottedName(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.DottedNameContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,i)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_exportStatement

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExportStatement" ):
                return visitor.visitExportStatement(self)
            else:
                return visitor.visitChildren(self)




    def exportStatement(self):

        localctx = OpenScenario2Parser.ExportStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 30, self.RULE_exportStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 273
            self.match(OpenScenario2Parser.EXPORT)
            self.state = 274
            self.dottedName()
            self.state = 279
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==47:
                self.state = 275
                self.match(OpenScenario2Parser.COMMA)
                self.state = 276
                self.dottedName()
                self.state = 281
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 282
            self.match(OpenScenario2Parser.NEWLINE)
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


        def variableDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.VariableDeclarationContext,0)


        def keepConstraint(self):
            return self.getTypedRuleContext(OpenScenario2Parser.KeepConstraintContext,0)


        def removeDefault(self):
            return self.getTypedRuleContext(OpenScenario2Parser.RemoveDefaultContext,0)


        def eventDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventDeclarationContext,0)


        def methodDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.MethodDeclarationContext,0)


        def coverageDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CoverageDeclarationContext,0)


        def onDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.OnDirectiveContext,0)


        def doDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DoDirectiveContext,0)


        def modifierInvocation(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ModifierInvocationContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_scenarioMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitScenarioMember" ):
                return visitor.visitScenarioMember(self)
            else:
                return visitor.visitChildren(self)




    def scenarioMember(self):

        localctx = OpenScenario2Parser.ScenarioMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 32, self.RULE_scenarioMember)
        try:
            self.state = 294
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,26,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 284
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 285
                self.variableDeclaration()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 286
                self.keepConstraint()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 287
                self.removeDefault()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 288
                self.eventDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 289
                self.methodDeclaration()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 290
                self.coverageDeclaration()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 291
                self.onDirective()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 292
                self.doDirective()
                pass

            elif la_ == 10:
                self.enterOuterAlt(localctx, 10)
                self.state = 293
                self.modifierInvocation()
                pass


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
            self.defaultValue = None # ExpressionContext

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def COLON(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COLON)
            else:
                return self.getToken(OpenScenario2Parser.COLON, i)

        def typeDeclarator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeDeclaratorContext,0)


        def WITH(self):
            return self.getToken(OpenScenario2Parser.WITH, 0)

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


        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def fieldConstraint(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.FieldConstraintContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.FieldConstraintContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_fieldDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFieldDeclaration" ):
                return visitor.visitFieldDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def fieldDeclaration(self):

        localctx = OpenScenario2Parser.FieldDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 34, self.RULE_fieldDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 296
            self.identifier()
            self.state = 301
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==47:
                self.state = 297
                self.match(OpenScenario2Parser.COMMA)
                self.state = 298
                self.identifier()
                self.state = 303
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 304
            self.match(OpenScenario2Parser.COLON)
            self.state = 305
            self.typeDeclarator()
            self.state = 308
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==57:
                self.state = 306
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 307
                localctx.defaultValue = self.expression(0)


            self.state = 325
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [32]:
                self.state = 310
                self.match(OpenScenario2Parser.WITH)
                self.state = 311
                self.match(OpenScenario2Parser.COLON)
                self.state = 322
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [76]:
                    self.state = 312
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 313
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 315 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 314
                        self.fieldConstraint()
                        self.state = 317 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not (_la==15 or _la==18):
                            break

                    self.state = 319
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [15, 18]:
                    self.state = 321
                    self.fieldConstraint()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [76]:
                self.state = 324
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


    class FieldConstraintContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def keepConstraint(self):
            return self.getTypedRuleContext(OpenScenario2Parser.KeepConstraintContext,0)


        def removeDefault(self):
            return self.getTypedRuleContext(OpenScenario2Parser.RemoveDefaultContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_fieldConstraint

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFieldConstraint" ):
                return visitor.visitFieldConstraint(self)
            else:
                return visitor.visitChildren(self)




    def fieldConstraint(self):

        localctx = OpenScenario2Parser.FieldConstraintContext(self, self._ctx, self.state)
        self.enterRule(localctx, 36, self.RULE_fieldConstraint)
        try:
            self.state = 329
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [15]:
                self.enterOuterAlt(localctx, 1)
                self.state = 327
                self.keepConstraint()
                pass
            elif token in [18]:
                self.enterOuterAlt(localctx, 2)
                self.state = 328
                self.removeDefault()
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


    class TypeDeclaratorContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def LIST(self):
            return self.getToken(OpenScenario2Parser.LIST, 0)

        def OF(self):
            return self.getToken(OpenScenario2Parser.OF, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_typeDeclarator

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitTypeDeclarator" ):
                return visitor.visitTypeDeclarator(self)
            else:
                return visitor.visitChildren(self)




    def typeDeclarator(self):

        localctx = OpenScenario2Parser.TypeDeclaratorContext(self, self._ctx, self.state)
        self.enterRule(localctx, 38, self.RULE_typeDeclarator)
        try:
            self.state = 335
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,33,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 331
                self.match(OpenScenario2Parser.LIST)
                self.state = 332
                self.match(OpenScenario2Parser.OF)
                self.state = 333
                self.identifier()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 334
                self.identifier()
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class VariableDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def VAR(self):
            return self.getToken(OpenScenario2Parser.VAR, 0)

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def typeDeclarator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeDeclaratorContext,0)


        def ASSIGN(self):
            return self.getToken(OpenScenario2Parser.ASSIGN, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_variableDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitVariableDeclaration" ):
                return visitor.visitVariableDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def variableDeclaration(self):

        localctx = OpenScenario2Parser.VariableDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 40, self.RULE_variableDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 337
            self.match(OpenScenario2Parser.VAR)
            self.state = 338
            self.identifier()
            self.state = 343
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==47:
                self.state = 339
                self.match(OpenScenario2Parser.COMMA)
                self.state = 340
                self.identifier()
                self.state = 345
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 348
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==48:
                self.state = 346
                self.match(OpenScenario2Parser.COLON)
                self.state = 347
                self.typeDeclarator()


            self.state = 352
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==57:
                self.state = 350
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 351
                self.expression(0)


            self.state = 354
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class KeepConstraintContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.strength = None # Token

        def KEEP(self):
            return self.getToken(OpenScenario2Parser.KEEP, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def DEFAULT(self):
            return self.getToken(OpenScenario2Parser.DEFAULT, 0)

        def HARD(self):
            return self.getToken(OpenScenario2Parser.HARD, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_keepConstraint

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitKeepConstraint" ):
                return visitor.visitKeepConstraint(self)
            else:
                return visitor.visitChildren(self)




    def keepConstraint(self):

        localctx = OpenScenario2Parser.KeepConstraintContext(self, self._ctx, self.state)
        self.enterRule(localctx, 42, self.RULE_keepConstraint)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 356
            self.match(OpenScenario2Parser.KEEP)
            self.state = 357
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 359
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,37,self._ctx)
            if la_ == 1:
                self.state = 358
                localctx.strength = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==16 or _la==17):
                    localctx.strength = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()


            self.state = 361
            self.expression(0)
            self.state = 362
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 363
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class RemoveDefaultContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def REMOVE_DEFAULT(self):
            return self.getToken(OpenScenario2Parser.REMOVE_DEFAULT, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_removeDefault

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRemoveDefault" ):
                return visitor.visitRemoveDefault(self)
            else:
                return visitor.visitChildren(self)




    def removeDefault(self):

        localctx = OpenScenario2Parser.RemoveDefaultContext(self, self._ctx, self.state)
        self.enterRule(localctx, 44, self.RULE_removeDefault)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 365
            self.match(OpenScenario2Parser.REMOVE_DEFAULT)
            self.state = 366
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 367
            self.expression(0)
            self.state = 368
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 369
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class EventDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EVENT(self):
            return self.getToken(OpenScenario2Parser.EVENT, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def IS(self):
            return self.getToken(OpenScenario2Parser.IS, 0)

        def eventSpecification(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventSpecificationContext,0)


        def parameterList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ParameterListContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_eventDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEventDeclaration" ):
                return visitor.visitEventDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def eventDeclaration(self):

        localctx = OpenScenario2Parser.EventDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 46, self.RULE_eventDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 371
            self.match(OpenScenario2Parser.EVENT)
            self.state = 372
            self.identifier()
            self.state = 378
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==65:
                self.state = 373
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 375
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 412342682120) != 0) or _la==74 or _la==75:
                    self.state = 374
                    self.parameterList()


                self.state = 377
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 382
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==20:
                self.state = 380
                self.match(OpenScenario2Parser.IS)
                self.state = 381
                self.eventSpecification()


            self.state = 384
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class EventSpecificationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def AT_SIGN(self):
            return self.getToken(OpenScenario2Parser.AT_SIGN, 0)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def IF(self):
            return self.getToken(OpenScenario2Parser.IF, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_eventSpecification

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEventSpecification" ):
                return visitor.visitEventSpecification(self)
            else:
                return visitor.visitChildren(self)




    def eventSpecification(self):

        localctx = OpenScenario2Parser.EventSpecificationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 48, self.RULE_eventSpecification)
        self._la = 0 # Token type
        try:
            self.state = 393
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [59]:
                self.enterOuterAlt(localctx, 1)
                self.state = 386
                self.match(OpenScenario2Parser.AT_SIGN)
                self.state = 387
                self.dottedName()
                self.state = 390
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==21:
                    self.state = 388
                    self.match(OpenScenario2Parser.IF)
                    self.state = 389
                    self.expression(0)


                pass
            elif token in [3, 9, 17, 19, 23, 24, 37, 38, 42, 43, 44, 60, 61, 65, 67, 69, 70, 71, 72, 73, 74, 75]:
                self.enterOuterAlt(localctx, 2)
                self.state = 392
                self.expression(0)
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


    class MethodDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def DEF(self):
            return self.getToken(OpenScenario2Parser.DEF, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def IS(self):
            return self.getToken(OpenScenario2Parser.IS, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def UNDEFINED(self):
            return self.getToken(OpenScenario2Parser.UNDEFINED, 0)

        def parameterList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ParameterListContext,0)


        def ARROW(self):
            return self.getToken(OpenScenario2Parser.ARROW, 0)

        def typeDeclarator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeDeclaratorContext,0)


        def EXTERNAL(self):
            return self.getToken(OpenScenario2Parser.EXTERNAL, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_methodDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMethodDeclaration" ):
                return visitor.visitMethodDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def methodDeclaration(self):

        localctx = OpenScenario2Parser.MethodDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 50, self.RULE_methodDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 395
            self.match(OpenScenario2Parser.DEF)
            self.state = 396
            self.identifier()
            self.state = 397
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 399
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 412342682120) != 0) or _la==74 or _la==75:
                self.state = 398
                self.parameterList()


            self.state = 401
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 404
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==49:
                self.state = 402
                self.match(OpenScenario2Parser.ARROW)
                self.state = 403
                self.typeDeclarator()


            self.state = 406
            self.match(OpenScenario2Parser.IS)
            self.state = 412
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,46,self._ctx)
            if la_ == 1:
                self.state = 408
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,45,self._ctx)
                if la_ == 1:
                    self.state = 407
                    self.match(OpenScenario2Parser.EXTERNAL)


                self.state = 410
                self.expression(0)
                pass

            elif la_ == 2:
                self.state = 411
                self.match(OpenScenario2Parser.UNDEFINED)
                pass


            self.state = 414
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ParameterListContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def parameter(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ParameterContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ParameterContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_parameterList

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitParameterList" ):
                return visitor.visitParameterList(self)
            else:
                return visitor.visitChildren(self)




    def parameterList(self):

        localctx = OpenScenario2Parser.ParameterListContext(self, self._ctx, self.state)
        self.enterRule(localctx, 52, self.RULE_parameterList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 416
            self.parameter()
            self.state = 421
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==47:
                self.state = 417
                self.match(OpenScenario2Parser.COMMA)
                self.state = 418
                self.parameter()
                self.state = 423
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ParameterContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def typeDeclarator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeDeclaratorContext,0)


        def ASSIGN(self):
            return self.getToken(OpenScenario2Parser.ASSIGN, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_parameter

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitParameter" ):
                return visitor.visitParameter(self)
            else:
                return visitor.visitChildren(self)




    def parameter(self):

        localctx = OpenScenario2Parser.ParameterContext(self, self._ctx, self.state)
        self.enterRule(localctx, 54, self.RULE_parameter)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 424
            self.identifier()
            self.state = 425
            self.match(OpenScenario2Parser.COLON)
            self.state = 426
            self.typeDeclarator()
            self.state = 429
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==57:
                self.state = 427
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 428
                self.expression(0)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class CoverageDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def COVER(self):
            return self.getToken(OpenScenario2Parser.COVER, 0)

        def RECORD(self):
            return self.getToken(OpenScenario2Parser.RECORD, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_coverageDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCoverageDeclaration" ):
                return visitor.visitCoverageDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def coverageDeclaration(self):

        localctx = OpenScenario2Parser.CoverageDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 56, self.RULE_coverageDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 431
            _la = self._input.LA(1)
            if not(_la==25 or _la==26):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 432
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 434
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                self.state = 433
                self.argumentList()


            self.state = 436
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 437
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class OnDirectiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ON(self):
            return self.getToken(OpenScenario2Parser.ON, 0)

        def eventSpecification(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventSpecificationContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def doMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.DoMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.DoMemberContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_onDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitOnDirective" ):
                return visitor.visitOnDirective(self)
            else:
                return visitor.visitChildren(self)




    def onDirective(self):

        localctx = OpenScenario2Parser.OnDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 58, self.RULE_onDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 439
            self.match(OpenScenario2Parser.ON)
            self.state = 440
            self.eventSpecification()
            self.state = 441
            self.match(OpenScenario2Parser.COLON)
            self.state = 442
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 443
            self.match(OpenScenario2Parser.INDENT)
            self.state = 445 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 444
                self.doMember()
                self.state = 447 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 536359862792) != 0) or _la==74 or _la==75):
                    break

            self.state = 449
            self.match(OpenScenario2Parser.DEDENT)
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

        def doMember(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DoMemberContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_doDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDoDirective" ):
                return visitor.visitDoDirective(self)
            else:
                return visitor.visitChildren(self)




    def doDirective(self):

        localctx = OpenScenario2Parser.DoDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 60, self.RULE_doDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 451
            self.match(OpenScenario2Parser.DO)
            self.state = 452
            self.doMember()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DoMemberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.label = None # IdentifierContext

        def composition(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CompositionContext,0)


        def behaviorInvocation(self):
            return self.getTypedRuleContext(OpenScenario2Parser.BehaviorInvocationContext,0)


        def waitDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.WaitDirectiveContext,0)


        def emitDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EmitDirectiveContext,0)


        def callDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CallDirectiveContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_doMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDoMember" ):
                return visitor.visitDoMember(self)
            else:
                return visitor.visitChildren(self)




    def doMember(self):

        localctx = OpenScenario2Parser.DoMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 62, self.RULE_doMember)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 457
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,51,self._ctx)
            if la_ == 1:
                self.state = 454
                localctx.label = self.identifier()
                self.state = 455
                self.match(OpenScenario2Parser.COLON)


            self.state = 464
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [29, 30, 31]:
                self.state = 459
                self.composition()
                pass
            elif token in [3, 9, 17, 19, 23, 24, 37, 38, 74, 75]:
                self.state = 460
                self.behaviorInvocation()
                pass
            elif token in [34]:
                self.state = 461
                self.waitDirective()
                pass
            elif token in [35]:
                self.state = 462
                self.emitDirective()
                pass
            elif token in [36]:
                self.state = 463
                self.callDirective()
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

        def doMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.DoMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.DoMemberContext,i)


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
        self.enterRule(localctx, 64, self.RULE_composition)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 466
            self.compositionOperator()
            self.state = 472
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==65:
                self.state = 467
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 469
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                    self.state = 468
                    self.argumentList()


                self.state = 471
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 474
            self.match(OpenScenario2Parser.COLON)
            self.state = 475
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 476
            self.match(OpenScenario2Parser.INDENT)
            self.state = 478 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 477
                self.doMember()
                self.state = 480 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 536359862792) != 0) or _la==74 or _la==75):
                    break

            self.state = 482
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
        self.enterRule(localctx, 66, self.RULE_compositionOperator)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 484
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 3758096384) != 0)):
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


    class BehaviorInvocationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.target = None # DottedNameContext

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def WITH(self):
            return self.getToken(OpenScenario2Parser.WITH, 0)

        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def INDENT(self):
            return self.getToken(OpenScenario2Parser.INDENT, 0)

        def DEDENT(self):
            return self.getToken(OpenScenario2Parser.DEDENT, 0)

        def behaviorWithMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.BehaviorWithMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.BehaviorWithMemberContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_behaviorInvocation

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitBehaviorInvocation" ):
                return visitor.visitBehaviorInvocation(self)
            else:
                return visitor.visitChildren(self)




    def behaviorInvocation(self):

        localctx = OpenScenario2Parser.BehaviorInvocationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 68, self.RULE_behaviorInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 486
            localctx.target = self.dottedName()
            self.state = 487
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 489
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                self.state = 488
                self.argumentList()


            self.state = 491
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 507
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [32]:
                self.state = 492
                self.match(OpenScenario2Parser.WITH)
                self.state = 493
                self.match(OpenScenario2Parser.COLON)
                self.state = 504
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [76]:
                    self.state = 494
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 495
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 497 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 496
                        self.behaviorWithMember()
                        self.state = 499 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 420932911624) != 0) or _la==74 or _la==75):
                            break

                    self.state = 501
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [3, 9, 15, 17, 18, 19, 23, 24, 33, 37, 38, 74, 75]:
                    self.state = 503
                    self.behaviorWithMember()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [76]:
                self.state = 506
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


    class BehaviorWithMemberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def modifierInvocation(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ModifierInvocationContext,0)


        def keepConstraint(self):
            return self.getTypedRuleContext(OpenScenario2Parser.KeepConstraintContext,0)


        def removeDefault(self):
            return self.getTypedRuleContext(OpenScenario2Parser.RemoveDefaultContext,0)


        def untilDirective(self):
            return self.getTypedRuleContext(OpenScenario2Parser.UntilDirectiveContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_behaviorWithMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitBehaviorWithMember" ):
                return visitor.visitBehaviorWithMember(self)
            else:
                return visitor.visitChildren(self)




    def behaviorWithMember(self):

        localctx = OpenScenario2Parser.BehaviorWithMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 70, self.RULE_behaviorWithMember)
        try:
            self.state = 513
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [3, 9, 17, 19, 23, 24, 37, 38, 74, 75]:
                self.enterOuterAlt(localctx, 1)
                self.state = 509
                self.modifierInvocation()
                pass
            elif token in [15]:
                self.enterOuterAlt(localctx, 2)
                self.state = 510
                self.keepConstraint()
                pass
            elif token in [18]:
                self.enterOuterAlt(localctx, 3)
                self.state = 511
                self.removeDefault()
                pass
            elif token in [33]:
                self.enterOuterAlt(localctx, 4)
                self.state = 512
                self.untilDirective()
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
            self.target = None # DottedNameContext

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


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
        self.enterRule(localctx, 72, self.RULE_modifierInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 515
            localctx.target = self.dottedName()
            self.state = 516
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 518
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                self.state = 517
                self.argumentList()


            self.state = 520
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 521
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UntilDirectiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def UNTIL(self):
            return self.getToken(OpenScenario2Parser.UNTIL, 0)

        def eventSpecification(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventSpecificationContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_untilDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUntilDirective" ):
                return visitor.visitUntilDirective(self)
            else:
                return visitor.visitChildren(self)




    def untilDirective(self):

        localctx = OpenScenario2Parser.UntilDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 74, self.RULE_untilDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 523
            self.match(OpenScenario2Parser.UNTIL)
            self.state = 524
            self.eventSpecification()
            self.state = 525
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class WaitDirectiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def WAIT(self):
            return self.getToken(OpenScenario2Parser.WAIT, 0)

        def eventSpecification(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventSpecificationContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_waitDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitWaitDirective" ):
                return visitor.visitWaitDirective(self)
            else:
                return visitor.visitChildren(self)




    def waitDirective(self):

        localctx = OpenScenario2Parser.WaitDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 76, self.RULE_waitDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 527
            self.match(OpenScenario2Parser.WAIT)
            self.state = 528
            self.eventSpecification()
            self.state = 529
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class EmitDirectiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EMIT(self):
            return self.getToken(OpenScenario2Parser.EMIT, 0)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_emitDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEmitDirective" ):
                return visitor.visitEmitDirective(self)
            else:
                return visitor.visitChildren(self)




    def emitDirective(self):

        localctx = OpenScenario2Parser.EmitDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 78, self.RULE_emitDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 531
            self.match(OpenScenario2Parser.EMIT)
            self.state = 532
            self.identifier()
            self.state = 538
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==65:
                self.state = 533
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 535
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                    self.state = 534
                    self.argumentList()


                self.state = 537
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 540
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class CallDirectiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def CALL(self):
            return self.getToken(OpenScenario2Parser.CALL, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_callDirective

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCallDirective" ):
                return visitor.visitCallDirective(self)
            else:
                return visitor.visitChildren(self)




    def callDirective(self):

        localctx = OpenScenario2Parser.CallDirectiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 80, self.RULE_callDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 542
            self.match(OpenScenario2Parser.CALL)
            self.state = 543
            self.expression(0)
            self.state = 544
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
        self.enterRule(localctx, 82, self.RULE_argumentList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 546
            self.argument()
            self.state = 551
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,64,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 547
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 548
                    self.argument() 
                self.state = 553
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,64,self._ctx)

            self.state = 555
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==47:
                self.state = 554
                self.match(OpenScenario2Parser.COMMA)


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
        self.enterRule(localctx, 84, self.RULE_argument)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 560
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,66,self._ctx)
            if la_ == 1:
                self.state = 557
                localctx.name = self.identifier()
                self.state = 558
                self.match(OpenScenario2Parser.COLON)


            self.state = 562
            self.expression(0)
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


    class PrimaryExpressionContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def primary(self):
            return self.getTypedRuleContext(OpenScenario2Parser.PrimaryContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPrimaryExpression" ):
                return visitor.visitPrimaryExpression(self)
            else:
                return visitor.visitChildren(self)


    class CallContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)
        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)
        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCall" ):
                return visitor.visitCall(self)
            else:
                return visitor.visitChildren(self)


    class MemberAccessContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)

        def DOT(self):
            return self.getToken(OpenScenario2Parser.DOT, 0)
        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMemberAccess" ):
                return visitor.visitMemberAccess(self)
            else:
                return visitor.visitChildren(self)


    class LogicalNotContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def NOT(self):
            return self.getToken(OpenScenario2Parser.NOT, 0)
        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitLogicalNot" ):
                return visitor.visitLogicalNot(self)
            else:
                return visitor.visitChildren(self)


    class ImplicationContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def IMPLIES(self):
            return self.getToken(OpenScenario2Parser.IMPLIES, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitImplication" ):
                return visitor.visitImplication(self)
            else:
                return visitor.visitChildren(self)


    class LogicalAndContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def AND(self):
            return self.getToken(OpenScenario2Parser.AND, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitLogicalAnd" ):
                return visitor.visitLogicalAnd(self)
            else:
                return visitor.visitChildren(self)


    class UnaryContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.op = None # Token
            self.copyFrom(ctx)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)

        def MINUS(self):
            return self.getToken(OpenScenario2Parser.MINUS, 0)
        def PLUS(self):
            return self.getToken(OpenScenario2Parser.PLUS, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnary" ):
                return visitor.visitUnary(self)
            else:
                return visitor.visitChildren(self)


    class MultiplicativeContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.op = None # Token
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def STAR(self):
            return self.getToken(OpenScenario2Parser.STAR, 0)
        def SLASH(self):
            return self.getToken(OpenScenario2Parser.SLASH, 0)
        def PERCENT(self):
            return self.getToken(OpenScenario2Parser.PERCENT, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMultiplicative" ):
                return visitor.visitMultiplicative(self)
            else:
                return visitor.visitChildren(self)


    class LogicalOrContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def OR(self):
            return self.getToken(OpenScenario2Parser.OR, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitLogicalOr" ):
                return visitor.visitLogicalOr(self)
            else:
                return visitor.visitChildren(self)


    class AdditiveContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.op = None # Token
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def PLUS(self):
            return self.getToken(OpenScenario2Parser.PLUS, 0)
        def MINUS(self):
            return self.getToken(OpenScenario2Parser.MINUS, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAdditive" ):
                return visitor.visitAdditive(self)
            else:
                return visitor.visitChildren(self)


    class RelationContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.op = None # Token
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def EQ(self):
            return self.getToken(OpenScenario2Parser.EQ, 0)
        def NE(self):
            return self.getToken(OpenScenario2Parser.NE, 0)
        def LT(self):
            return self.getToken(OpenScenario2Parser.LT, 0)
        def LE(self):
            return self.getToken(OpenScenario2Parser.LE, 0)
        def GT(self):
            return self.getToken(OpenScenario2Parser.GT, 0)
        def GE(self):
            return self.getToken(OpenScenario2Parser.GE, 0)
        def IN(self):
            return self.getToken(OpenScenario2Parser.IN, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRelation" ):
                return visitor.visitRelation(self)
            else:
                return visitor.visitChildren(self)



    def expression(self, _p:int=0):
        _parentctx = self._ctx
        _parentState = self.state
        localctx = OpenScenario2Parser.ExpressionContext(self, self._ctx, _parentState)
        _prevctx = localctx
        _startState = 86
        self.enterRecursionRule(localctx, 86, self.RULE_expression, _p)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 570
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [60, 61]:
                localctx = OpenScenario2Parser.UnaryContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx

                self.state = 565
                localctx.op = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==60 or _la==61):
                    localctx.op = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                self.state = 566
                self.expression(9)
                pass
            elif token in [42]:
                localctx = OpenScenario2Parser.LogicalNotContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 567
                self.match(OpenScenario2Parser.NOT)
                self.state = 568
                self.expression(5)
                pass
            elif token in [3, 9, 17, 19, 23, 24, 37, 38, 43, 44, 65, 67, 69, 70, 71, 72, 73, 74, 75]:
                localctx = OpenScenario2Parser.PrimaryExpressionContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 569
                self.primary()
                pass
            else:
                raise NoViableAltException(self)

            self._ctx.stop = self._input.LT(-1)
            self.state = 601
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,70,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    if self._parseListeners is not None:
                        self.triggerExitRuleEvent()
                    _prevctx = localctx
                    self.state = 599
                    self._errHandler.sync(self)
                    la_ = self._interp.adaptivePredict(self._input,69,self._ctx)
                    if la_ == 1:
                        localctx = OpenScenario2Parser.MultiplicativeContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 572
                        if not self.precpred(self._ctx, 8):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 8)")
                        self.state = 573
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(((((_la - 62)) & ~0x3f) == 0 and ((1 << (_la - 62)) & 7) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 574
                        self.expression(9)
                        pass

                    elif la_ == 2:
                        localctx = OpenScenario2Parser.AdditiveContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 575
                        if not self.precpred(self._ctx, 7):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 7)")
                        self.state = 576
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(_la==60 or _la==61):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 577
                        self.expression(8)
                        pass

                    elif la_ == 3:
                        localctx = OpenScenario2Parser.RelationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 578
                        if not self.precpred(self._ctx, 6):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 6)")
                        self.state = 579
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 141863938017984512) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 580
                        self.expression(7)
                        pass

                    elif la_ == 4:
                        localctx = OpenScenario2Parser.LogicalAndContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 581
                        if not self.precpred(self._ctx, 4):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 4)")
                        self.state = 582
                        self.match(OpenScenario2Parser.AND)
                        self.state = 583
                        self.expression(5)
                        pass

                    elif la_ == 5:
                        localctx = OpenScenario2Parser.LogicalOrContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 584
                        if not self.precpred(self._ctx, 3):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 3)")
                        self.state = 585
                        self.match(OpenScenario2Parser.OR)
                        self.state = 586
                        self.expression(4)
                        pass

                    elif la_ == 6:
                        localctx = OpenScenario2Parser.ImplicationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 587
                        if not self.precpred(self._ctx, 2):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 2)")
                        self.state = 588
                        self.match(OpenScenario2Parser.IMPLIES)
                        self.state = 589
                        self.expression(2)
                        pass

                    elif la_ == 7:
                        localctx = OpenScenario2Parser.MemberAccessContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 590
                        if not self.precpred(self._ctx, 11):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 11)")
                        self.state = 591
                        self.match(OpenScenario2Parser.DOT)
                        self.state = 592
                        self.identifier()
                        pass

                    elif la_ == 8:
                        localctx = OpenScenario2Parser.CallContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 593
                        if not self.precpred(self._ctx, 10):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 10)")
                        self.state = 594
                        self.match(OpenScenario2Parser.LPAREN)
                        self.state = 596
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                            self.state = 595
                            self.argumentList()


                        self.state = 598
                        self.match(OpenScenario2Parser.RPAREN)
                        pass

             
                self.state = 603
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,70,self._ctx)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.unrollRecursionContexts(_parentctx)
        return localctx


    class PrimaryContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_primary

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class RangePrimaryContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def rangeLiteral(self):
            return self.getTypedRuleContext(OpenScenario2Parser.RangeLiteralContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRangePrimary" ):
                return visitor.visitRangePrimary(self)
            else:
                return visitor.visitChildren(self)


    class EnumValueContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.enumType = None # IdentifierContext
            self.member = None # IdentifierContext
            self.copyFrom(ctx)

        def BANG(self):
            return self.getToken(OpenScenario2Parser.BANG, 0)
        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEnumValue" ):
                return visitor.visitEnumValue(self)
            else:
                return visitor.visitChildren(self)


    class PhysicalLiteralContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def PhysicalLiteral(self):
            return self.getToken(OpenScenario2Parser.PhysicalLiteral, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPhysicalLiteral" ):
                return visitor.visitPhysicalLiteral(self)
            else:
                return visitor.visitChildren(self)


    class StringLiteralContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def StringLiteral(self):
            return self.getToken(OpenScenario2Parser.StringLiteral, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStringLiteral" ):
                return visitor.visitStringLiteral(self)
            else:
                return visitor.visitChildren(self)


    class ListLiteralContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LBRACK(self):
            return self.getToken(OpenScenario2Parser.LBRACK, 0)
        def RBRACK(self):
            return self.getToken(OpenScenario2Parser.RBRACK, 0)
        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitListLiteral" ):
                return visitor.visitListLiteral(self)
            else:
                return visitor.visitChildren(self)


    class BoolLiteralContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def TRUE(self):
            return self.getToken(OpenScenario2Parser.TRUE, 0)
        def FALSE(self):
            return self.getToken(OpenScenario2Parser.FALSE, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitBoolLiteral" ):
                return visitor.visitBoolLiteral(self)
            else:
                return visitor.visitChildren(self)


    class ParenthesisedContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
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


    class NumberLiteralContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def IntLiteral(self):
            return self.getToken(OpenScenario2Parser.IntLiteral, 0)
        def FloatLiteral(self):
            return self.getToken(OpenScenario2Parser.FloatLiteral, 0)
        def HexLiteral(self):
            return self.getToken(OpenScenario2Parser.HexLiteral, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNumberLiteral" ):
                return visitor.visitNumberLiteral(self)
            else:
                return visitor.visitChildren(self)


    class NamePrimaryContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNamePrimary" ):
                return visitor.visitNamePrimary(self)
            else:
                return visitor.visitChildren(self)



    def primary(self):

        localctx = OpenScenario2Parser.PrimaryContext(self, self._ctx, self.state)
        self.enterRule(localctx, 88, self.RULE_primary)
        self._la = 0 # Token type
        try:
            self.state = 633
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,74,self._ctx)
            if la_ == 1:
                localctx = OpenScenario2Parser.PhysicalLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 604
                self.match(OpenScenario2Parser.PhysicalLiteral)
                pass

            elif la_ == 2:
                localctx = OpenScenario2Parser.NumberLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 605
                _la = self._input.LA(1)
                if not(((((_la - 69)) & ~0x3f) == 0 and ((1 << (_la - 69)) & 13) != 0)):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 3:
                localctx = OpenScenario2Parser.StringLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 606
                self.match(OpenScenario2Parser.StringLiteral)
                pass

            elif la_ == 4:
                localctx = OpenScenario2Parser.BoolLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 607
                _la = self._input.LA(1)
                if not(_la==43 or _la==44):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 5:
                localctx = OpenScenario2Parser.RangePrimaryContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 608
                self.rangeLiteral()
                pass

            elif la_ == 6:
                localctx = OpenScenario2Parser.ListLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 609
                self.match(OpenScenario2Parser.LBRACK)
                self.state = 621
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 3458795712488800776) != 0) or ((((_la - 65)) & ~0x3f) == 0 and ((1 << (_la - 65)) & 2037) != 0):
                    self.state = 610
                    self.expression(0)
                    self.state = 615
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,71,self._ctx)
                    while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                        if _alt==1:
                            self.state = 611
                            self.match(OpenScenario2Parser.COMMA)
                            self.state = 612
                            self.expression(0) 
                        self.state = 617
                        self._errHandler.sync(self)
                        _alt = self._interp.adaptivePredict(self._input,71,self._ctx)

                    self.state = 619
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if _la==47:
                        self.state = 618
                        self.match(OpenScenario2Parser.COMMA)




                self.state = 623
                self.match(OpenScenario2Parser.RBRACK)
                pass

            elif la_ == 7:
                localctx = OpenScenario2Parser.EnumValueContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 624
                localctx.enumType = self.identifier()
                self.state = 625
                self.match(OpenScenario2Parser.BANG)
                self.state = 626
                localctx.member = self.identifier()
                pass

            elif la_ == 8:
                localctx = OpenScenario2Parser.NamePrimaryContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 628
                self.identifier()
                pass

            elif la_ == 9:
                localctx = OpenScenario2Parser.ParenthesisedContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 629
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 630
                self.expression(0)
                self.state = 631
                self.match(OpenScenario2Parser.RPAREN)
                pass


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
            self.unit = None # Token

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


        def Identifier(self):
            return self.getToken(OpenScenario2Parser.Identifier, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_rangeLiteral

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRangeLiteral" ):
                return visitor.visitRangeLiteral(self)
            else:
                return visitor.visitChildren(self)




    def rangeLiteral(self):

        localctx = OpenScenario2Parser.RangeLiteralContext(self, self._ctx, self.state)
        self.enterRule(localctx, 90, self.RULE_rangeLiteral)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 635
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 636
            localctx.low = self.expression(0)
            self.state = 637
            self.match(OpenScenario2Parser.DOUBLEDOT)
            self.state = 638
            localctx.high = self.expression(0)
            self.state = 639
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 641
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,75,self._ctx)
            if la_ == 1:
                self.state = 640
                localctx.unit = self.match(OpenScenario2Parser.Identifier)


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
        self.enterRule(localctx, 92, self.RULE_dottedName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 643
            self.identifier()
            self.state = 648
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==46:
                self.state = 644
                self.match(OpenScenario2Parser.DOT)
                self.state = 645
                self.identifier()
                self.state = 650
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

        def QuotedIdentifier(self):
            return self.getToken(OpenScenario2Parser.QuotedIdentifier, 0)

        def ACTION(self):
            return self.getToken(OpenScenario2Parser.ACTION, 0)

        def MODIFIER(self):
            return self.getToken(OpenScenario2Parser.MODIFIER, 0)

        def EVENT(self):
            return self.getToken(OpenScenario2Parser.EVENT, 0)

        def HARD(self):
            return self.getToken(OpenScenario2Parser.HARD, 0)

        def LIST(self):
            return self.getToken(OpenScenario2Parser.LIST, 0)

        def OF(self):
            return self.getToken(OpenScenario2Parser.OF, 0)

        def EXTERNAL(self):
            return self.getToken(OpenScenario2Parser.EXTERNAL, 0)

        def UNDEFINED(self):
            return self.getToken(OpenScenario2Parser.UNDEFINED, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_identifier

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIdentifier" ):
                return visitor.visitIdentifier(self)
            else:
                return visitor.visitChildren(self)




    def identifier(self):

        localctx = OpenScenario2Parser.IdentifierContext(self, self._ctx, self.state)
        self.enterRule(localctx, 94, self.RULE_identifier)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 651
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 412342682120) != 0) or _la==74 or _la==75):
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



    def sempred(self, localctx:RuleContext, ruleIndex:int, predIndex:int):
        if self._predicates == None:
            self._predicates = dict()
        self._predicates[43] = self.expression_sempred
        pred = self._predicates.get(ruleIndex, None)
        if pred is None:
            raise Exception("No predicate with index:" + str(ruleIndex))
        else:
            return pred(localctx, predIndex)

    def expression_sempred(self, localctx:ExpressionContext, predIndex:int):
            if predIndex == 0:
                return self.precpred(self._ctx, 8)
         

            if predIndex == 1:
                return self.precpred(self._ctx, 7)
         

            if predIndex == 2:
                return self.precpred(self._ctx, 6)
         

            if predIndex == 3:
                return self.precpred(self._ctx, 4)
         

            if predIndex == 4:
                return self.precpred(self._ctx, 3)
         

            if predIndex == 5:
                return self.precpred(self._ctx, 2)
         

            if predIndex == 6:
                return self.precpred(self._ctx, 11)
         

            if predIndex == 7:
                return self.precpred(self._ctx, 10)
         




