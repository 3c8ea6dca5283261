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
        4,1,83,680,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,2,43,7,43,2,44,7,44,2,45,7,45,2,46,
        7,46,2,47,7,47,2,48,7,48,2,49,7,49,1,0,1,0,1,0,5,0,104,8,0,10,0,
        12,0,107,9,0,1,0,1,0,1,1,1,1,1,1,3,1,114,8,1,1,1,1,1,1,2,1,2,1,2,
        1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,3,2,129,8,2,1,3,1,3,1,3,3,3,134,
        8,3,1,3,1,3,1,3,1,3,4,3,140,8,3,11,3,12,3,141,1,3,1,3,1,3,3,3,147,
        8,3,1,4,1,4,1,4,3,4,152,8,4,1,4,1,4,1,5,1,5,1,5,1,5,1,5,1,5,3,5,
        162,8,5,1,6,1,6,1,6,3,6,167,8,6,1,6,1,6,1,6,1,6,4,6,173,8,6,11,6,
        12,6,174,1,6,1,6,1,6,3,6,180,8,6,1,7,1,7,1,7,3,7,185,8,7,1,7,1,7,
        1,7,1,7,4,7,191,8,7,11,7,12,7,192,1,7,1,7,1,7,3,7,198,8,7,1,8,1,
        8,1,8,1,8,1,8,1,8,3,8,206,8,8,1,9,1,9,1,9,1,9,1,9,1,9,1,9,1,9,1,
        9,1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,11,1,
        11,1,11,1,11,1,11,1,11,1,11,5,11,235,8,11,10,11,12,11,238,9,11,1,
        11,3,11,241,8,11,1,11,1,11,1,11,1,12,1,12,1,12,3,12,249,8,12,1,13,
        1,13,1,13,1,14,1,14,1,14,1,14,1,14,1,14,4,14,260,8,14,11,14,12,14,
        261,1,14,1,14,1,15,1,15,1,15,1,15,3,15,270,8,15,1,15,1,15,1,15,1,
        15,4,15,276,8,15,11,15,12,15,277,1,15,1,15,1,15,3,15,283,8,15,1,
        16,1,16,1,16,1,16,1,16,1,16,5,16,291,8,16,10,16,12,16,294,9,16,3,
        16,296,8,16,1,16,1,16,1,17,1,17,1,17,1,17,5,17,304,8,17,10,17,12,
        17,307,9,17,1,17,1,17,1,18,1,18,1,18,1,18,1,18,1,18,1,18,1,18,1,
        18,1,18,3,18,321,8,18,1,19,1,19,1,19,5,19,326,8,19,10,19,12,19,329,
        9,19,1,19,1,19,1,19,1,19,3,19,335,8,19,1,19,1,19,1,19,1,19,1,19,
        4,19,342,8,19,11,19,12,19,343,1,19,1,19,1,19,3,19,349,8,19,1,19,
        3,19,352,8,19,1,20,1,20,3,20,356,8,20,1,21,1,21,1,21,1,21,3,21,362,
        8,21,1,22,1,22,1,22,1,22,5,22,368,8,22,10,22,12,22,371,9,22,1,22,
        1,22,3,22,375,8,22,1,22,1,22,3,22,379,8,22,1,22,1,22,1,23,1,23,1,
        23,3,23,386,8,23,1,23,1,23,1,23,1,23,1,24,1,24,1,24,1,24,1,24,1,
        24,1,25,1,25,1,25,1,25,3,25,402,8,25,1,25,3,25,405,8,25,1,25,1,25,
        3,25,409,8,25,1,25,1,25,1,26,1,26,1,26,1,26,3,26,417,8,26,1,26,3,
        26,420,8,26,1,27,1,27,1,27,1,27,3,27,426,8,27,1,27,1,27,1,27,3,27,
        431,8,27,1,27,1,27,3,27,435,8,27,1,27,1,27,3,27,439,8,27,1,27,1,
        27,1,28,1,28,1,28,5,28,446,8,28,10,28,12,28,449,9,28,1,29,1,29,1,
        29,1,29,1,29,3,29,456,8,29,1,30,1,30,1,30,3,30,461,8,30,1,30,1,30,
        1,30,1,31,1,31,1,31,1,31,1,31,1,31,4,31,472,8,31,11,31,12,31,473,
        1,31,1,31,1,32,1,32,1,32,1,33,1,33,1,33,3,33,484,8,33,1,33,1,33,
        1,33,1,33,1,33,3,33,491,8,33,1,34,1,34,1,34,3,34,496,8,34,1,34,3,
        34,499,8,34,1,34,1,34,1,34,1,34,4,34,505,8,34,11,34,12,34,506,1,
        34,1,34,1,35,1,35,1,36,1,36,1,36,3,36,516,8,36,1,36,1,36,1,36,1,
        36,1,36,1,36,4,36,524,8,36,11,36,12,36,525,1,36,1,36,1,36,3,36,531,
        8,36,1,36,3,36,534,8,36,1,37,1,37,1,37,1,37,3,37,540,8,37,1,38,1,
        38,1,38,3,38,545,8,38,1,38,1,38,1,38,1,39,1,39,1,39,1,39,1,40,1,
        40,1,40,1,40,1,41,1,41,1,41,1,41,3,41,562,8,41,1,41,3,41,565,8,41,
        1,41,1,41,1,42,1,42,1,42,1,42,1,43,1,43,1,43,5,43,576,8,43,10,43,
        12,43,579,9,43,1,43,3,43,582,8,43,1,44,1,44,1,44,3,44,587,8,44,1,
        44,1,44,1,45,1,45,1,45,1,45,1,45,1,45,3,45,597,8,45,1,45,1,45,1,
        45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,
        45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,1,45,3,45,623,8,45,1,45,5,
        45,626,8,45,10,45,12,45,629,9,45,1,46,1,46,1,46,1,46,1,46,1,46,1,
        46,1,46,1,46,5,46,640,8,46,10,46,12,46,643,9,46,1,46,3,46,646,8,
        46,3,46,648,8,46,1,46,1,46,1,46,1,46,1,46,1,46,1,46,1,46,1,46,1,
        46,3,46,660,8,46,1,47,1,47,1,47,1,47,1,47,1,47,3,47,668,8,47,1,48,
        1,48,1,48,5,48,673,8,48,10,48,12,48,676,9,48,1,49,1,49,1,49,0,1,
        90,50,0,2,4,6,8,10,12,14,16,18,20,22,24,26,28,30,32,34,36,38,40,
        42,44,46,48,50,52,54,56,58,60,62,64,66,68,70,72,74,76,78,80,82,84,
        86,88,90,92,94,96,98,0,11,1,0,2,3,2,0,71,71,74,74,1,0,18,19,1,0,
        27,28,1,0,31,33,1,0,62,63,1,0,64,66,2,0,41,41,53,58,2,0,71,71,73,
        74,1,0,45,46,8,0,3,3,7,8,11,11,19,19,21,21,25,26,39,40,76,77,747,
        0,105,1,0,0,0,2,110,1,0,0,0,4,128,1,0,0,0,6,130,1,0,0,0,8,151,1,
        0,0,0,10,155,1,0,0,0,12,163,1,0,0,0,14,181,1,0,0,0,16,205,1,0,0,
        0,18,207,1,0,0,0,20,216,1,0,0,0,22,227,1,0,0,0,24,245,1,0,0,0,26,
        250,1,0,0,0,28,253,1,0,0,0,30,265,1,0,0,0,32,284,1,0,0,0,34,299,
        1,0,0,0,36,320,1,0,0,0,38,322,1,0,0,0,40,355,1,0,0,0,42,361,1,0,
        0,0,44,363,1,0,0,0,46,382,1,0,0,0,48,391,1,0,0,0,50,397,1,0,0,0,
        52,419,1,0,0,0,54,421,1,0,0,0,56,442,1,0,0,0,58,450,1,0,0,0,60,457,
        1,0,0,0,62,465,1,0,0,0,64,477,1,0,0,0,66,483,1,0,0,0,68,492,1,0,
        0,0,70,510,1,0,0,0,72,512,1,0,0,0,74,539,1,0,0,0,76,541,1,0,0,0,
        78,549,1,0,0,0,80,553,1,0,0,0,82,557,1,0,0,0,84,568,1,0,0,0,86,572,
        1,0,0,0,88,586,1,0,0,0,90,596,1,0,0,0,92,659,1,0,0,0,94,661,1,0,
        0,0,96,669,1,0,0,0,98,677,1,0,0,0,100,104,3,2,1,0,101,104,3,4,2,
        0,102,104,5,78,0,0,103,100,1,0,0,0,103,101,1,0,0,0,103,102,1,0,0,
        0,104,107,1,0,0,0,105,103,1,0,0,0,105,106,1,0,0,0,106,108,1,0,0,
        0,107,105,1,0,0,0,108,109,5,0,0,1,109,1,1,0,0,0,110,113,5,1,0,0,
        111,114,5,75,0,0,112,114,3,96,48,0,113,111,1,0,0,0,113,112,1,0,0,
        0,114,115,1,0,0,0,115,116,5,78,0,0,116,3,1,0,0,0,117,129,3,6,3,0,
        118,129,3,18,9,0,119,129,3,20,10,0,120,129,3,12,6,0,121,129,3,14,
        7,0,122,129,3,22,11,0,123,129,3,26,13,0,124,129,3,28,14,0,125,129,
        3,30,15,0,126,129,3,32,16,0,127,129,3,34,17,0,128,117,1,0,0,0,128,
        118,1,0,0,0,128,119,1,0,0,0,128,120,1,0,0,0,128,121,1,0,0,0,128,
        122,1,0,0,0,128,123,1,0,0,0,128,124,1,0,0,0,128,125,1,0,0,0,128,
        126,1,0,0,0,128,127,1,0,0,0,129,5,1,0,0,0,130,131,7,0,0,0,131,133,
        3,8,4,0,132,134,3,10,5,0,133,132,1,0,0,0,133,134,1,0,0,0,134,146,
        1,0,0,0,135,136,5,50,0,0,136,137,5,78,0,0,137,139,5,82,0,0,138,140,
        3,36,18,0,139,138,1,0,0,0,140,141,1,0,0,0,141,139,1,0,0,0,141,142,
        1,0,0,0,142,143,1,0,0,0,143,144,5,83,0,0,144,147,1,0,0,0,145,147,
        5,78,0,0,146,135,1,0,0,0,146,145,1,0,0,0,147,7,1,0,0,0,148,149,3,
        98,49,0,149,150,5,48,0,0,150,152,1,0,0,0,151,148,1,0,0,0,151,152,
        1,0,0,0,152,153,1,0,0,0,153,154,3,98,49,0,154,9,1,0,0,0,155,156,
        5,15,0,0,156,161,3,8,4,0,157,158,5,67,0,0,158,159,3,90,45,0,159,
        160,5,68,0,0,160,162,1,0,0,0,161,157,1,0,0,0,161,162,1,0,0,0,162,
        11,1,0,0,0,163,164,5,4,0,0,164,166,3,98,49,0,165,167,3,10,5,0,166,
        165,1,0,0,0,166,167,1,0,0,0,167,179,1,0,0,0,168,169,5,50,0,0,169,
        170,5,78,0,0,170,172,5,82,0,0,171,173,3,16,8,0,172,171,1,0,0,0,173,
        174,1,0,0,0,174,172,1,0,0,0,174,175,1,0,0,0,175,176,1,0,0,0,176,
        177,5,83,0,0,177,180,1,0,0,0,178,180,5,78,0,0,179,168,1,0,0,0,179,
        178,1,0,0,0,180,13,1,0,0,0,181,182,5,5,0,0,182,184,3,98,49,0,183,
        185,3,10,5,0,184,183,1,0,0,0,184,185,1,0,0,0,185,197,1,0,0,0,186,
        187,5,50,0,0,187,188,5,78,0,0,188,190,5,82,0,0,189,191,3,16,8,0,
        190,189,1,0,0,0,191,192,1,0,0,0,192,190,1,0,0,0,192,193,1,0,0,0,
        193,194,1,0,0,0,194,195,5,83,0,0,195,198,1,0,0,0,196,198,5,78,0,
        0,197,186,1,0,0,0,197,196,1,0,0,0,198,15,1,0,0,0,199,206,3,38,19,
        0,200,206,3,46,23,0,201,206,3,48,24,0,202,206,3,50,25,0,203,206,
        3,54,27,0,204,206,3,60,30,0,205,199,1,0,0,0,205,200,1,0,0,0,205,
        201,1,0,0,0,205,202,1,0,0,0,205,203,1,0,0,0,205,204,1,0,0,0,206,
        17,1,0,0,0,207,208,5,7,0,0,208,209,3,98,49,0,209,210,5,22,0,0,210,
        211,3,98,49,0,211,212,5,67,0,0,212,213,3,86,43,0,213,214,5,68,0,
        0,214,215,5,78,0,0,215,19,1,0,0,0,216,217,5,8,0,0,217,218,3,98,49,
        0,218,219,5,40,0,0,219,220,3,98,49,0,220,221,5,22,0,0,221,222,3,
        98,49,0,222,223,5,67,0,0,223,224,3,86,43,0,224,225,5,68,0,0,225,
        226,5,78,0,0,226,21,1,0,0,0,227,228,5,6,0,0,228,229,3,98,49,0,229,
        230,5,50,0,0,230,231,5,69,0,0,231,236,3,24,12,0,232,233,5,49,0,0,
        233,235,3,24,12,0,234,232,1,0,0,0,235,238,1,0,0,0,236,234,1,0,0,
        0,236,237,1,0,0,0,237,240,1,0,0,0,238,236,1,0,0,0,239,241,5,49,0,
        0,240,239,1,0,0,0,240,241,1,0,0,0,241,242,1,0,0,0,242,243,5,70,0,
        0,243,244,5,78,0,0,244,23,1,0,0,0,245,248,3,98,49,0,246,247,5,59,
        0,0,247,249,7,1,0,0,248,246,1,0,0,0,248,249,1,0,0,0,249,25,1,0,0,
        0,250,251,5,9,0,0,251,252,3,38,19,0,252,27,1,0,0,0,253,254,5,10,
        0,0,254,255,3,8,4,0,255,256,5,50,0,0,256,257,5,78,0,0,257,259,5,
        82,0,0,258,260,3,36,18,0,259,258,1,0,0,0,260,261,1,0,0,0,261,259,
        1,0,0,0,261,262,1,0,0,0,262,263,1,0,0,0,263,264,5,83,0,0,264,29,
        1,0,0,0,265,266,5,11,0,0,266,269,3,8,4,0,267,268,5,40,0,0,268,270,
        3,98,49,0,269,267,1,0,0,0,269,270,1,0,0,0,270,282,1,0,0,0,271,272,
        5,50,0,0,272,273,5,78,0,0,273,275,5,82,0,0,274,276,3,36,18,0,275,
        274,1,0,0,0,276,277,1,0,0,0,277,275,1,0,0,0,277,278,1,0,0,0,278,
        279,1,0,0,0,279,280,5,83,0,0,280,283,1,0,0,0,281,283,5,78,0,0,282,
        271,1,0,0,0,282,281,1,0,0,0,283,31,1,0,0,0,284,285,5,12,0,0,285,
        295,3,98,49,0,286,287,5,13,0,0,287,292,3,98,49,0,288,289,5,49,0,
        0,289,291,3,98,49,0,290,288,1,0,0,0,291,294,1,0,0,0,292,290,1,0,
        0,0,292,293,1,0,0,0,293,296,1,0,0,0,294,292,1,0,0,0,295,286,1,0,
        0,0,295,296,1,0,0,0,296,297,1,0,0,0,297,298,5,78,0,0,298,33,1,0,
        0,0,299,300,5,14,0,0,300,305,3,96,48,0,301,302,5,49,0,0,302,304,
        3,96,48,0,303,301,1,0,0,0,304,307,1,0,0,0,305,303,1,0,0,0,305,306,
        1,0,0,0,306,308,1,0,0,0,307,305,1,0,0,0,308,309,5,78,0,0,309,35,
        1,0,0,0,310,321,3,38,19,0,311,321,3,44,22,0,312,321,3,46,23,0,313,
        321,3,48,24,0,314,321,3,50,25,0,315,321,3,54,27,0,316,321,3,60,30,
        0,317,321,3,62,31,0,318,321,3,64,32,0,319,321,3,76,38,0,320,310,
        1,0,0,0,320,311,1,0,0,0,320,312,1,0,0,0,320,313,1,0,0,0,320,314,
        1,0,0,0,320,315,1,0,0,0,320,316,1,0,0,0,320,317,1,0,0,0,320,318,
        1,0,0,0,320,319,1,0,0,0,321,37,1,0,0,0,322,327,3,98,49,0,323,324,
        5,49,0,0,324,326,3,98,49,0,325,323,1,0,0,0,326,329,1,0,0,0,327,325,
        1,0,0,0,327,328,1,0,0,0,328,330,1,0,0,0,329,327,1,0,0,0,330,331,
        5,50,0,0,331,334,3,42,21,0,332,333,5,59,0,0,333,335,3,90,45,0,334,
        332,1,0,0,0,334,335,1,0,0,0,335,351,1,0,0,0,336,337,5,34,0,0,337,
        348,5,50,0,0,338,339,5,78,0,0,339,341,5,82,0,0,340,342,3,40,20,0,
        341,340,1,0,0,0,342,343,1,0,0,0,343,341,1,0,0,0,343,344,1,0,0,0,
        344,345,1,0,0,0,345,346,5,83,0,0,346,349,1,0,0,0,347,349,3,40,20,
        0,348,338,1,0,0,0,348,347,1,0,0,0,349,352,1,0,0,0,350,352,5,78,0,
        0,351,336,1,0,0,0,351,350,1,0,0,0,352,39,1,0,0,0,353,356,3,46,23,
        0,354,356,3,48,24,0,355,353,1,0,0,0,355,354,1,0,0,0,356,41,1,0,0,
        0,357,358,5,39,0,0,358,359,5,40,0,0,359,362,3,98,49,0,360,362,3,
        98,49,0,361,357,1,0,0,0,361,360,1,0,0,0,362,43,1,0,0,0,363,364,5,
        16,0,0,364,369,3,98,49,0,365,366,5,49,0,0,366,368,3,98,49,0,367,
        365,1,0,0,0,368,371,1,0,0,0,369,367,1,0,0,0,369,370,1,0,0,0,370,
        374,1,0,0,0,371,369,1,0,0,0,372,373,5,50,0,0,373,375,3,42,21,0,374,
        372,1,0,0,0,374,375,1,0,0,0,375,378,1,0,0,0,376,377,5,59,0,0,377,
        379,3,90,45,0,378,376,1,0,0,0,378,379,1,0,0,0,379,380,1,0,0,0,380,
        381,5,78,0,0,381,45,1,0,0,0,382,383,5,17,0,0,383,385,5,67,0,0,384,
        386,7,2,0,0,385,384,1,0,0,0,385,386,1,0,0,0,386,387,1,0,0,0,387,
        388,3,90,45,0,388,389,5,68,0,0,389,390,5,78,0,0,390,47,1,0,0,0,391,
        392,5,20,0,0,392,393,5,67,0,0,393,394,3,90,45,0,394,395,5,68,0,0,
        395,396,5,78,0,0,396,49,1,0,0,0,397,398,5,21,0,0,398,404,3,98,49,
        0,399,401,5,67,0,0,400,402,3,56,28,0,401,400,1,0,0,0,401,402,1,0,
        0,0,402,403,1,0,0,0,403,405,5,68,0,0,404,399,1,0,0,0,404,405,1,0,
        0,0,405,408,1,0,0,0,406,407,5,22,0,0,407,409,3,52,26,0,408,406,1,
        0,0,0,408,409,1,0,0,0,409,410,1,0,0,0,410,411,5,78,0,0,411,51,1,
        0,0,0,412,413,5,61,0,0,413,416,3,96,48,0,414,415,5,23,0,0,415,417,
        3,90,45,0,416,414,1,0,0,0,416,417,1,0,0,0,417,420,1,0,0,0,418,420,
        3,90,45,0,419,412,1,0,0,0,419,418,1,0,0,0,420,53,1,0,0,0,421,422,
        5,24,0,0,422,423,3,98,49,0,423,425,5,67,0,0,424,426,3,56,28,0,425,
        424,1,0,0,0,425,426,1,0,0,0,426,427,1,0,0,0,427,430,5,68,0,0,428,
        429,5,51,0,0,429,431,3,42,21,0,430,428,1,0,0,0,430,431,1,0,0,0,431,
        432,1,0,0,0,432,438,5,22,0,0,433,435,5,25,0,0,434,433,1,0,0,0,434,
        435,1,0,0,0,435,436,1,0,0,0,436,439,3,90,45,0,437,439,5,26,0,0,438,
        434,1,0,0,0,438,437,1,0,0,0,439,440,1,0,0,0,440,441,5,78,0,0,441,
        55,1,0,0,0,442,447,3,58,29,0,443,444,5,49,0,0,444,446,3,58,29,0,
        445,443,1,0,0,0,446,449,1,0,0,0,447,445,1,0,0,0,447,448,1,0,0,0,
        448,57,1,0,0,0,449,447,1,0,0,0,450,451,3,98,49,0,451,452,5,50,0,
        0,452,455,3,42,21,0,453,454,5,59,0,0,454,456,3,90,45,0,455,453,1,
        0,0,0,455,456,1,0,0,0,456,59,1,0,0,0,457,458,7,3,0,0,458,460,5,67,
        0,0,459,461,3,86,43,0,460,459,1,0,0,0,460,461,1,0,0,0,461,462,1,
        0,0,0,462,463,5,68,0,0,463,464,5,78,0,0,464,61,1,0,0,0,465,466,5,
        29,0,0,466,467,3,52,26,0,467,468,5,50,0,0,468,469,5,78,0,0,469,471,
        5,82,0,0,470,472,3,66,33,0,471,470,1,0,0,0,472,473,1,0,0,0,473,471,
        1,0,0,0,473,474,1,0,0,0,474,475,1,0,0,0,475,476,5,83,0,0,476,63,
        1,0,0,0,477,478,5,30,0,0,478,479,3,66,33,0,479,65,1,0,0,0,480,481,
        3,98,49,0,481,482,5,50,0,0,482,484,1,0,0,0,483,480,1,0,0,0,483,484,
        1,0,0,0,484,490,1,0,0,0,485,491,3,68,34,0,486,491,3,72,36,0,487,
        491,3,80,40,0,488,491,3,82,41,0,489,491,3,84,42,0,490,485,1,0,0,
        0,490,486,1,0,0,0,490,487,1,0,0,0,490,488,1,0,0,0,490,489,1,0,0,
        0,491,67,1,0,0,0,492,498,3,70,35,0,493,495,5,67,0,0,494,496,3,86,
        43,0,495,494,1,0,0,0,495,496,1,0,0,0,496,497,1,0,0,0,497,499,5,68,
        0,0,498,493,1,0,0,0,498,499,1,0,0,0,499,500,1,0,0,0,500,501,5,50,
        0,0,501,502,5,78,0,0,502,504,5,82,0,0,503,505,3,66,33,0,504,503,
        1,0,0,0,505,506,1,0,0,0,506,504,1,0,0,0,506,507,1,0,0,0,507,508,
        1,0,0,0,508,509,5,83,0,0,509,69,1,0,0,0,510,511,7,4,0,0,511,71,1,
        0,0,0,512,513,3,96,48,0,513,515,5,67,0,0,514,516,3,86,43,0,515,514,
        1,0,0,0,515,516,1,0,0,0,516,517,1,0,0,0,517,533,5,68,0,0,518,519,
        5,34,0,0,519,530,5,50,0,0,520,521,5,78,0,0,521,523,5,82,0,0,522,
        524,3,74,37,0,523,522,1,0,0,0,524,525,1,0,0,0,525,523,1,0,0,0,525,
        526,1,0,0,0,526,527,1,0,0,0,527,528,5,83,0,0,528,531,1,0,0,0,529,
        531,3,74,37,0,530,520,1,0,0,0,530,529,1,0,0,0,531,534,1,0,0,0,532,
        534,5,78,0,0,533,518,1,0,0,0,533,532,1,0,0,0,534,73,1,0,0,0,535,
        540,3,76,38,0,536,540,3,46,23,0,537,540,3,48,24,0,538,540,3,78,39,
        0,539,535,1,0,0,0,539,536,1,0,0,0,539,537,1,0,0,0,539,538,1,0,0,
        0,540,75,1,0,0,0,541,542,3,96,48,0,542,544,5,67,0,0,543,545,3,86,
        43,0,544,543,1,0,0,0,544,545,1,0,0,0,545,546,1,0,0,0,546,547,5,68,
        0,0,547,548,5,78,0,0,548,77,1,0,0,0,549,550,5,35,0,0,550,551,3,52,
        26,0,551,552,5,78,0,0,552,79,1,0,0,0,553,554,5,36,0,0,554,555,3,
        52,26,0,555,556,5,78,0,0,556,81,1,0,0,0,557,558,5,37,0,0,558,564,
        3,98,49,0,559,561,5,67,0,0,560,562,3,86,43,0,561,560,1,0,0,0,561,
        562,1,0,0,0,562,563,1,0,0,0,563,565,5,68,0,0,564,559,1,0,0,0,564,
        565,1,0,0,0,565,566,1,0,0,0,566,567,5,78,0,0,567,83,1,0,0,0,568,
        569,5,38,0,0,569,570,3,90,45,0,570,571,5,78,0,0,571,85,1,0,0,0,572,
        577,3,88,44,0,573,574,5,49,0,0,574,576,3,88,44,0,575,573,1,0,0,0,
        576,579,1,0,0,0,577,575,1,0,0,0,577,578,1,0,0,0,578,581,1,0,0,0,
        579,577,1,0,0,0,580,582,5,49,0,0,581,580,1,0,0,0,581,582,1,0,0,0,
        582,87,1,0,0,0,583,584,3,98,49,0,584,585,5,50,0,0,585,587,1,0,0,
        0,586,583,1,0,0,0,586,587,1,0,0,0,587,588,1,0,0,0,588,589,3,90,45,
        0,589,89,1,0,0,0,590,591,6,45,-1,0,591,592,7,5,0,0,592,597,3,90,
        45,9,593,594,5,44,0,0,594,597,3,90,45,5,595,597,3,92,46,0,596,590,
        1,0,0,0,596,593,1,0,0,0,596,595,1,0,0,0,597,627,1,0,0,0,598,599,
        10,8,0,0,599,600,7,6,0,0,600,626,3,90,45,9,601,602,10,7,0,0,602,
        603,7,5,0,0,603,626,3,90,45,8,604,605,10,6,0,0,605,606,7,7,0,0,606,
        626,3,90,45,7,607,608,10,4,0,0,608,609,5,42,0,0,609,626,3,90,45,
        5,610,611,10,3,0,0,611,612,5,43,0,0,612,626,3,90,45,4,613,614,10,
        2,0,0,614,615,5,52,0,0,615,626,3,90,45,2,616,617,10,11,0,0,617,618,
        5,48,0,0,618,626,3,98,49,0,619,620,10,10,0,0,620,622,5,67,0,0,621,
        623,3,86,43,0,622,621,1,0,0,0,622,623,1,0,0,0,623,624,1,0,0,0,624,
        626,5,68,0,0,625,598,1,0,0,0,625,601,1,0,0,0,625,604,1,0,0,0,625,
        607,1,0,0,0,625,610,1,0,0,0,625,613,1,0,0,0,625,616,1,0,0,0,625,
        619,1,0,0,0,626,629,1,0,0,0,627,625,1,0,0,0,627,628,1,0,0,0,628,
        91,1,0,0,0,629,627,1,0,0,0,630,660,5,72,0,0,631,660,7,8,0,0,632,
        660,5,75,0,0,633,660,7,9,0,0,634,660,3,94,47,0,635,647,5,69,0,0,
        636,641,3,90,45,0,637,638,5,49,0,0,638,640,3,90,45,0,639,637,1,0,
        0,0,640,643,1,0,0,0,641,639,1,0,0,0,641,642,1,0,0,0,642,645,1,0,
        0,0,643,641,1,0,0,0,644,646,5,49,0,0,645,644,1,0,0,0,645,646,1,0,
        0,0,646,648,1,0,0,0,647,636,1,0,0,0,647,648,1,0,0,0,648,649,1,0,
        0,0,649,660,5,70,0,0,650,651,3,98,49,0,651,652,5,60,0,0,652,653,
        3,98,49,0,653,660,1,0,0,0,654,660,3,98,49,0,655,656,5,67,0,0,656,
        657,3,90,45,0,657,658,5,68,0,0,658,660,1,0,0,0,659,630,1,0,0,0,659,
        631,1,0,0,0,659,632,1,0,0,0,659,633,1,0,0,0,659,634,1,0,0,0,659,
        635,1,0,0,0,659,650,1,0,0,0,659,654,1,0,0,0,659,655,1,0,0,0,660,
        93,1,0,0,0,661,662,5,69,0,0,662,663,3,90,45,0,663,664,5,47,0,0,664,
        665,3,90,45,0,665,667,5,70,0,0,666,668,5,76,0,0,667,666,1,0,0,0,
        667,668,1,0,0,0,668,95,1,0,0,0,669,674,3,98,49,0,670,671,5,48,0,
        0,671,673,3,98,49,0,672,670,1,0,0,0,673,676,1,0,0,0,674,672,1,0,
        0,0,674,675,1,0,0,0,675,97,1,0,0,0,676,674,1,0,0,0,677,678,7,10,
        0,0,678,99,1,0,0,0,77,103,105,113,128,133,141,146,151,161,166,174,
        179,184,192,197,205,236,240,248,261,269,277,282,292,295,305,320,
        327,334,343,348,351,355,361,369,374,378,385,401,404,408,416,419,
        425,430,434,438,447,455,460,473,483,490,495,498,506,515,525,530,
        533,539,544,561,564,577,581,586,596,622,625,627,641,645,647,659,
        667,674
    ]

class OpenScenario2Parser ( Parser ):

    grammarFileName = "OpenScenario2.g4"

    atn = ATNDeserializer().deserialize(serializedATN())

    decisionsToDFA = [ DFA(ds, i) for i, ds in enumerate(atn.decisionToState) ]

    sharedContextCache = PredictionContextCache()

    literalNames = [ "<INVALID>", "'import'", "'scenario'", "'action'", 
                     "'actor'", "'struct'", "'enum'", "'type'", "'unit'", 
                     "'global'", "'extend'", "'modifier'", "'namespace'", 
                     "'use'", "'export'", "'inherits'", "'var'", "'keep'", 
                     "'default'", "'hard'", "'remove_default'", "'event'", 
                     "'is'", "'if'", "'def'", "'external'", "'undefined'", 
                     "'cover'", "'record'", "'on'", "'do'", "'serial'", 
                     "'parallel'", "'one_of'", "'with'", "'until'", "'wait'", 
                     "'emit'", "'call'", "'list'", "'of'", "'in'", "'and'", 
                     "'or'", "'not'", "'true'", "'false'", "'..'", "'.'", 
                     "','", "':'", "'->'", "'=>'", "'=='", "'!='", "'<='", 
                     "'>='", "'<'", "'>'", "'='", "'!'", "'@'", "'+'", "'-'", 
                     "'*'", "'/'", "'%'", "'('", "')'", "'['", "']'" ]

    symbolicNames = [ "<INVALID>", "IMPORT", "SCENARIO", "ACTION", "ACTOR", 
                      "STRUCT", "ENUM", "TYPE", "UNIT", "GLOBAL", "EXTEND", 
                      "MODIFIER", "NAMESPACE", "USE", "EXPORT", "INHERITS", 
                      "VAR", "KEEP", "DEFAULT", "HARD", "REMOVE_DEFAULT", 
                      "EVENT", "IS", "IF", "DEF", "EXTERNAL", "UNDEFINED", 
                      "COVER", "RECORD", "ON", "DO", "SERIAL", "PARALLEL", 
                      "ONE_OF", "WITH", "UNTIL", "WAIT", "EMIT", "CALL", 
                      "LIST", "OF", "IN", "AND", "OR", "NOT", "TRUE", "FALSE", 
                      "DOUBLEDOT", "DOT", "COMMA", "COLON", "ARROW", "IMPLIES", 
                      "EQ", "NE", "LE", "GE", "LT", "GT", "ASSIGN", "BANG", 
                      "AT_SIGN", "PLUS", "MINUS", "STAR", "SLASH", "PERCENT", 
                      "LPAREN", "RPAREN", "LBRACK", "RBRACK", "HexLiteral", 
                      "PhysicalLiteral", "FloatLiteral", "IntLiteral", "StringLiteral", 
                      "Identifier", "QuotedIdentifier", "NEWLINE", "LINE_JOIN", 
                      "WS", "COMMENT", "INDENT", "DEDENT" ]

    RULE_oscFile = 0
    RULE_importStatement = 1
    RULE_declaration = 2
    RULE_scenarioDeclaration = 3
    RULE_behaviorName = 4
    RULE_inheritance = 5
    RULE_actorDeclaration = 6
    RULE_structDeclaration = 7
    RULE_structMember = 8
    RULE_physicalTypeDeclaration = 9
    RULE_unitDeclaration = 10
    RULE_enumDeclaration = 11
    RULE_enumMember = 12
    RULE_globalDeclaration = 13
    RULE_extendDeclaration = 14
    RULE_modifierDeclaration = 15
    RULE_namespaceStatement = 16
    RULE_exportStatement = 17
    RULE_scenarioMember = 18
    RULE_fieldDeclaration = 19
    RULE_fieldConstraint = 20
    RULE_typeDeclarator = 21
    RULE_variableDeclaration = 22
    RULE_keepConstraint = 23
    RULE_removeDefault = 24
    RULE_eventDeclaration = 25
    RULE_eventSpecification = 26
    RULE_methodDeclaration = 27
    RULE_parameterList = 28
    RULE_parameter = 29
    RULE_coverageDeclaration = 30
    RULE_onDirective = 31
    RULE_doDirective = 32
    RULE_doMember = 33
    RULE_composition = 34
    RULE_compositionOperator = 35
    RULE_behaviorInvocation = 36
    RULE_behaviorWithMember = 37
    RULE_modifierInvocation = 38
    RULE_untilDirective = 39
    RULE_waitDirective = 40
    RULE_emitDirective = 41
    RULE_callDirective = 42
    RULE_argumentList = 43
    RULE_argument = 44
    RULE_expression = 45
    RULE_primary = 46
    RULE_rangeLiteral = 47
    RULE_dottedName = 48
    RULE_identifier = 49

    ruleNames =  [ "oscFile", "importStatement", "declaration", "scenarioDeclaration", 
                   "behaviorName", "inheritance", "actorDeclaration", "structDeclaration", 
                   "structMember", "physicalTypeDeclaration", "unitDeclaration", 
                   "enumDeclaration", "enumMember", "globalDeclaration", 
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
    TYPE=7
    UNIT=8
    GLOBAL=9
    EXTEND=10
    MODIFIER=11
    NAMESPACE=12
    USE=13
    EXPORT=14
    INHERITS=15
    VAR=16
    KEEP=17
    DEFAULT=18
    HARD=19
    REMOVE_DEFAULT=20
    EVENT=21
    IS=22
    IF=23
    DEF=24
    EXTERNAL=25
    UNDEFINED=26
    COVER=27
    RECORD=28
    ON=29
    DO=30
    SERIAL=31
    PARALLEL=32
    ONE_OF=33
    WITH=34
    UNTIL=35
    WAIT=36
    EMIT=37
    CALL=38
    LIST=39
    OF=40
    IN=41
    AND=42
    OR=43
    NOT=44
    TRUE=45
    FALSE=46
    DOUBLEDOT=47
    DOT=48
    COMMA=49
    COLON=50
    ARROW=51
    IMPLIES=52
    EQ=53
    NE=54
    LE=55
    GE=56
    LT=57
    GT=58
    ASSIGN=59
    BANG=60
    AT_SIGN=61
    PLUS=62
    MINUS=63
    STAR=64
    SLASH=65
    PERCENT=66
    LPAREN=67
    RPAREN=68
    LBRACK=69
    RBRACK=70
    HexLiteral=71
    PhysicalLiteral=72
    FloatLiteral=73
    IntLiteral=74
    StringLiteral=75
    Identifier=76
    QuotedIdentifier=77
    NEWLINE=78
    LINE_JOIN=79
    WS=80
    COMMENT=81
    INDENT=82
    DEDENT=83

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
            self.state = 105
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while (((_la) & ~0x3f) == 0 and ((1 << _la) & 24574) != 0) or _la==78:
                self.state = 103
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [1]:
                    self.state = 100
                    self.importStatement()
                    pass
                elif token in [2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 14]:
                    self.state = 101
                    self.declaration()
                    pass
                elif token in [78]:
                    self.state = 102
                    self.match(OpenScenario2Parser.NEWLINE)
                    pass
                else:
                    raise NoViableAltException(self)

                self.state = 107
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 108
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
            self.state = 110
            self.match(OpenScenario2Parser.IMPORT)
            self.state = 113
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [75]:
                self.state = 111
                self.match(OpenScenario2Parser.StringLiteral)
                pass
            elif token in [3, 7, 8, 11, 19, 21, 25, 26, 39, 40, 76, 77]:
                self.state = 112
                self.dottedName()
                pass
            else:
                raise NoViableAltException(self)

            self.state = 115
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


        def physicalTypeDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.PhysicalTypeDeclarationContext,0)


        def unitDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.UnitDeclarationContext,0)


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
            self.state = 128
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [2, 3]:
                self.enterOuterAlt(localctx, 1)
                self.state = 117
                self.scenarioDeclaration()
                pass
            elif token in [7]:
                self.enterOuterAlt(localctx, 2)
                self.state = 118
                self.physicalTypeDeclaration()
                pass
            elif token in [8]:
                self.enterOuterAlt(localctx, 3)
                self.state = 119
                self.unitDeclaration()
                pass
            elif token in [4]:
                self.enterOuterAlt(localctx, 4)
                self.state = 120
                self.actorDeclaration()
                pass
            elif token in [5]:
                self.enterOuterAlt(localctx, 5)
                self.state = 121
                self.structDeclaration()
                pass
            elif token in [6]:
                self.enterOuterAlt(localctx, 6)
                self.state = 122
                self.enumDeclaration()
                pass
            elif token in [9]:
                self.enterOuterAlt(localctx, 7)
                self.state = 123
                self.globalDeclaration()
                pass
            elif token in [10]:
                self.enterOuterAlt(localctx, 8)
                self.state = 124
                self.extendDeclaration()
                pass
            elif token in [11]:
                self.enterOuterAlt(localctx, 9)
                self.state = 125
                self.modifierDeclaration()
                pass
            elif token in [12]:
                self.enterOuterAlt(localctx, 10)
                self.state = 126
                self.namespaceStatement()
                pass
            elif token in [14]:
                self.enterOuterAlt(localctx, 11)
                self.state = 127
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
            self.state = 130
            localctx.kind = self._input.LT(1)
            _la = self._input.LA(1)
            if not(_la==2 or _la==3):
                localctx.kind = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 131
            self.behaviorName()
            self.state = 133
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 132
                self.inheritance()


            self.state = 146
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [50]:
                self.state = 135
                self.match(OpenScenario2Parser.COLON)
                self.state = 136
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 137
                self.match(OpenScenario2Parser.INDENT)
                self.state = 139 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 138
                    self.scenarioMember()
                    self.state = 141 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 1651402017160) != 0) or _la==76 or _la==77):
                        break

                self.state = 143
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [78]:
                self.state = 145
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
            self.state = 151
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,7,self._ctx)
            if la_ == 1:
                self.state = 148
                localctx.actorType = self.identifier()
                self.state = 149
                self.match(OpenScenario2Parser.DOT)


            self.state = 153
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
            self.state = 155
            self.match(OpenScenario2Parser.INHERITS)
            self.state = 156
            localctx.parent = self.behaviorName()
            self.state = 161
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==67:
                self.state = 157
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 158
                localctx.condition = self.expression(0)
                self.state = 159
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
            self.state = 163
            self.match(OpenScenario2Parser.ACTOR)
            self.state = 164
            self.identifier()
            self.state = 166
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 165
                self.inheritance()


            self.state = 179
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [50]:
                self.state = 168
                self.match(OpenScenario2Parser.COLON)
                self.state = 169
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 170
                self.match(OpenScenario2Parser.INDENT)
                self.state = 172 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 171
                    self.structMember()
                    self.state = 174 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 1649791338888) != 0) or _la==76 or _la==77):
                        break

                self.state = 176
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [78]:
                self.state = 178
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
            self.state = 181
            self.match(OpenScenario2Parser.STRUCT)
            self.state = 182
            self.identifier()
            self.state = 184
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 183
                self.inheritance()


            self.state = 197
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [50]:
                self.state = 186
                self.match(OpenScenario2Parser.COLON)
                self.state = 187
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 188
                self.match(OpenScenario2Parser.INDENT)
                self.state = 190 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 189
                    self.structMember()
                    self.state = 192 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 1649791338888) != 0) or _la==76 or _la==77):
                        break

                self.state = 194
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [78]:
                self.state = 196
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
            self.state = 205
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,15,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 199
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 200
                self.keepConstraint()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 201
                self.removeDefault()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 202
                self.eventDeclaration()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 203
                self.methodDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 204
                self.coverageDeclaration()
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class PhysicalTypeDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.name = None # IdentifierContext
            self.si = None # IdentifierContext

        def TYPE(self):
            return self.getToken(OpenScenario2Parser.TYPE, 0)

        def IS(self):
            return self.getToken(OpenScenario2Parser.IS, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_physicalTypeDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPhysicalTypeDeclaration" ):
                return visitor.visitPhysicalTypeDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def physicalTypeDeclaration(self):

        localctx = OpenScenario2Parser.PhysicalTypeDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 18, self.RULE_physicalTypeDeclaration)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 207
            self.match(OpenScenario2Parser.TYPE)
            self.state = 208
            localctx.name = self.identifier()
            self.state = 209
            self.match(OpenScenario2Parser.IS)
            self.state = 210
            localctx.si = self.identifier()
            self.state = 211
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 212
            self.argumentList()
            self.state = 213
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 214
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitDeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.name = None # IdentifierContext
            self.type_ = None # IdentifierContext
            self.si = None # IdentifierContext

        def UNIT(self):
            return self.getToken(OpenScenario2Parser.UNIT, 0)

        def OF(self):
            return self.getToken(OpenScenario2Parser.OF, 0)

        def IS(self):
            return self.getToken(OpenScenario2Parser.IS, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def identifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.IdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,i)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_unitDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitDeclaration" ):
                return visitor.visitUnitDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def unitDeclaration(self):

        localctx = OpenScenario2Parser.UnitDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 20, self.RULE_unitDeclaration)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 216
            self.match(OpenScenario2Parser.UNIT)
            self.state = 217
            localctx.name = self.identifier()
            self.state = 218
            self.match(OpenScenario2Parser.OF)
            self.state = 219
            localctx.type_ = self.identifier()
            self.state = 220
            self.match(OpenScenario2Parser.IS)
            self.state = 221
            localctx.si = self.identifier()
            self.state = 222
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 223
            self.argumentList()
            self.state = 224
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 225
            self.match(OpenScenario2Parser.NEWLINE)
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
        self.enterRule(localctx, 22, self.RULE_enumDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 227
            self.match(OpenScenario2Parser.ENUM)
            self.state = 228
            self.identifier()
            self.state = 229
            self.match(OpenScenario2Parser.COLON)
            self.state = 230
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 231
            self.enumMember()
            self.state = 236
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,16,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 232
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 233
                    self.enumMember() 
                self.state = 238
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,16,self._ctx)

            self.state = 240
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==49:
                self.state = 239
                self.match(OpenScenario2Parser.COMMA)


            self.state = 242
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 243
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
        self.enterRule(localctx, 24, self.RULE_enumMember)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 245
            self.identifier()
            self.state = 248
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==59:
                self.state = 246
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 247
                _la = self._input.LA(1)
                if not(_la==71 or _la==74):
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
        self.enterRule(localctx, 26, self.RULE_globalDeclaration)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 250
            self.match(OpenScenario2Parser.GLOBAL)
            self.state = 251
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
        self.enterRule(localctx, 28, self.RULE_extendDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 253
            self.match(OpenScenario2Parser.EXTEND)
            self.state = 254
            self.behaviorName()
            self.state = 255
            self.match(OpenScenario2Parser.COLON)
            self.state = 256
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 257
            self.match(OpenScenario2Parser.INDENT)
            self.state = 259 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 258
                self.scenarioMember()
                self.state = 261 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 1651402017160) != 0) or _la==76 or _la==77):
                    break

            self.state = 263
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
        self.enterRule(localctx, 30, self.RULE_modifierDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 265
            self.match(OpenScenario2Parser.MODIFIER)
            self.state = 266
            self.behaviorName()
            self.state = 269
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==40:
                self.state = 267
                self.match(OpenScenario2Parser.OF)
                self.state = 268
                self.identifier()


            self.state = 282
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [50]:
                self.state = 271
                self.match(OpenScenario2Parser.COLON)
                self.state = 272
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 273
                self.match(OpenScenario2Parser.INDENT)
                self.state = 275 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 274
                    self.scenarioMember()
                    self.state = 277 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 1651402017160) != 0) or _la==76 or _la==77):
                        break

                self.state = 279
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [78]:
                self.state = 281
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
        self.enterRule(localctx, 32, self.RULE_namespaceStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 284
            self.match(OpenScenario2Parser.NAMESPACE)
            self.state = 285
            self.identifier()
            self.state = 295
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==13:
                self.state = 286
                self.match(OpenScenario2Parser.USE)
                self.state = 287
                self.identifier()
                self.state = 292
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==49:
                    self.state = 288
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 289
                    self.identifier()
                    self.state = 294
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)



            self.state = 297
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
        self.enterRule(localctx, 34, self.RULE_exportStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 299
            self.match(OpenScenario2Parser.EXPORT)
            self.state = 300
            self.dottedName()
            self.state = 305
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==49:
                self.state = 301
                self.match(OpenScenario2Parser.COMMA)
                self.state = 302
                self.dottedName()
                self.state = 307
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 308
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
        self.enterRule(localctx, 36, self.RULE_scenarioMember)
        try:
            self.state = 320
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,26,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 310
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 311
                self.variableDeclaration()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 312
                self.keepConstraint()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 313
                self.removeDefault()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 314
                self.eventDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 315
                self.methodDeclaration()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 316
                self.coverageDeclaration()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 317
                self.onDirective()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 318
                self.doDirective()
                pass

            elif la_ == 10:
                self.enterOuterAlt(localctx, 10)
                self.state = 319
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
        self.enterRule(localctx, 38, self.RULE_fieldDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 322
            self.identifier()
            self.state = 327
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==49:
                self.state = 323
                self.match(OpenScenario2Parser.COMMA)
                self.state = 324
                self.identifier()
                self.state = 329
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 330
            self.match(OpenScenario2Parser.COLON)
            self.state = 331
            self.typeDeclarator()
            self.state = 334
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==59:
                self.state = 332
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 333
                localctx.defaultValue = self.expression(0)


            self.state = 351
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                self.state = 336
                self.match(OpenScenario2Parser.WITH)
                self.state = 337
                self.match(OpenScenario2Parser.COLON)
                self.state = 348
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [78]:
                    self.state = 338
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 339
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 341 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 340
                        self.fieldConstraint()
                        self.state = 343 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not (_la==17 or _la==20):
                            break

                    self.state = 345
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [17, 20]:
                    self.state = 347
                    self.fieldConstraint()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [78]:
                self.state = 350
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
        self.enterRule(localctx, 40, self.RULE_fieldConstraint)
        try:
            self.state = 355
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [17]:
                self.enterOuterAlt(localctx, 1)
                self.state = 353
                self.keepConstraint()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 354
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
        self.enterRule(localctx, 42, self.RULE_typeDeclarator)
        try:
            self.state = 361
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,33,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 357
                self.match(OpenScenario2Parser.LIST)
                self.state = 358
                self.match(OpenScenario2Parser.OF)
                self.state = 359
                self.identifier()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 360
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
        self.enterRule(localctx, 44, self.RULE_variableDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 363
            self.match(OpenScenario2Parser.VAR)
            self.state = 364
            self.identifier()
            self.state = 369
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==49:
                self.state = 365
                self.match(OpenScenario2Parser.COMMA)
                self.state = 366
                self.identifier()
                self.state = 371
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 374
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==50:
                self.state = 372
                self.match(OpenScenario2Parser.COLON)
                self.state = 373
                self.typeDeclarator()


            self.state = 378
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==59:
                self.state = 376
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 377
                self.expression(0)


            self.state = 380
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
        self.enterRule(localctx, 46, self.RULE_keepConstraint)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 382
            self.match(OpenScenario2Parser.KEEP)
            self.state = 383
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 385
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,37,self._ctx)
            if la_ == 1:
                self.state = 384
                localctx.strength = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==18 or _la==19):
                    localctx.strength = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()


            self.state = 387
            self.expression(0)
            self.state = 388
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 389
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
        self.enterRule(localctx, 48, self.RULE_removeDefault)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 391
            self.match(OpenScenario2Parser.REMOVE_DEFAULT)
            self.state = 392
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 393
            self.expression(0)
            self.state = 394
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 395
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
        self.enterRule(localctx, 50, self.RULE_eventDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 397
            self.match(OpenScenario2Parser.EVENT)
            self.state = 398
            self.identifier()
            self.state = 404
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==67:
                self.state = 399
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 401
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1649370728840) != 0) or _la==76 or _la==77:
                    self.state = 400
                    self.parameterList()


                self.state = 403
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 408
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==22:
                self.state = 406
                self.match(OpenScenario2Parser.IS)
                self.state = 407
                self.eventSpecification()


            self.state = 410
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
        self.enterRule(localctx, 52, self.RULE_eventSpecification)
        self._la = 0 # Token type
        try:
            self.state = 419
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [61]:
                self.enterOuterAlt(localctx, 1)
                self.state = 412
                self.match(OpenScenario2Parser.AT_SIGN)
                self.state = 413
                self.dottedName()
                self.state = 416
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==23:
                    self.state = 414
                    self.match(OpenScenario2Parser.IF)
                    self.state = 415
                    self.expression(0)


                pass
            elif token in [3, 7, 8, 11, 19, 21, 25, 26, 39, 40, 44, 45, 46, 62, 63, 67, 69, 71, 72, 73, 74, 75, 76, 77]:
                self.enterOuterAlt(localctx, 2)
                self.state = 418
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
        self.enterRule(localctx, 54, self.RULE_methodDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 421
            self.match(OpenScenario2Parser.DEF)
            self.state = 422
            self.identifier()
            self.state = 423
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 425
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1649370728840) != 0) or _la==76 or _la==77:
                self.state = 424
                self.parameterList()


            self.state = 427
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 430
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==51:
                self.state = 428
                self.match(OpenScenario2Parser.ARROW)
                self.state = 429
                self.typeDeclarator()


            self.state = 432
            self.match(OpenScenario2Parser.IS)
            self.state = 438
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,46,self._ctx)
            if la_ == 1:
                self.state = 434
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,45,self._ctx)
                if la_ == 1:
                    self.state = 433
                    self.match(OpenScenario2Parser.EXTERNAL)


                self.state = 436
                self.expression(0)
                pass

            elif la_ == 2:
                self.state = 437
                self.match(OpenScenario2Parser.UNDEFINED)
                pass


            self.state = 440
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
        self.enterRule(localctx, 56, self.RULE_parameterList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 442
            self.parameter()
            self.state = 447
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==49:
                self.state = 443
                self.match(OpenScenario2Parser.COMMA)
                self.state = 444
                self.parameter()
                self.state = 449
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
        self.enterRule(localctx, 58, self.RULE_parameter)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 450
            self.identifier()
            self.state = 451
            self.match(OpenScenario2Parser.COLON)
            self.state = 452
            self.typeDeclarator()
            self.state = 455
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==59:
                self.state = 453
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 454
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
        self.enterRule(localctx, 60, self.RULE_coverageDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 457
            _la = self._input.LA(1)
            if not(_la==27 or _la==28):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 458
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 460
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                self.state = 459
                self.argumentList()


            self.state = 462
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 463
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
        self.enterRule(localctx, 62, self.RULE_onDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 465
            self.match(OpenScenario2Parser.ON)
            self.state = 466
            self.eventSpecification()
            self.state = 467
            self.match(OpenScenario2Parser.COLON)
            self.state = 468
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 469
            self.match(OpenScenario2Parser.INDENT)
            self.state = 471 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 470
                self.doMember()
                self.state = 473 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2145439451528) != 0) or _la==76 or _la==77):
                    break

            self.state = 475
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
        self.enterRule(localctx, 64, self.RULE_doDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 477
            self.match(OpenScenario2Parser.DO)
            self.state = 478
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
        self.enterRule(localctx, 66, self.RULE_doMember)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 483
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,51,self._ctx)
            if la_ == 1:
                self.state = 480
                localctx.label = self.identifier()
                self.state = 481
                self.match(OpenScenario2Parser.COLON)


            self.state = 490
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [31, 32, 33]:
                self.state = 485
                self.composition()
                pass
            elif token in [3, 7, 8, 11, 19, 21, 25, 26, 39, 40, 76, 77]:
                self.state = 486
                self.behaviorInvocation()
                pass
            elif token in [36]:
                self.state = 487
                self.waitDirective()
                pass
            elif token in [37]:
                self.state = 488
                self.emitDirective()
                pass
            elif token in [38]:
                self.state = 489
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
        self.enterRule(localctx, 68, self.RULE_composition)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 492
            self.compositionOperator()
            self.state = 498
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==67:
                self.state = 493
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 495
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                    self.state = 494
                    self.argumentList()


                self.state = 497
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 500
            self.match(OpenScenario2Parser.COLON)
            self.state = 501
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 502
            self.match(OpenScenario2Parser.INDENT)
            self.state = 504 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 503
                self.doMember()
                self.state = 506 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2145439451528) != 0) or _la==76 or _la==77):
                    break

            self.state = 508
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
        self.enterRule(localctx, 70, self.RULE_compositionOperator)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 510
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 15032385536) != 0)):
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
        self.enterRule(localctx, 72, self.RULE_behaviorInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 512
            localctx.target = self.dottedName()
            self.state = 513
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 515
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                self.state = 514
                self.argumentList()


            self.state = 517
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 533
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                self.state = 518
                self.match(OpenScenario2Parser.WITH)
                self.state = 519
                self.match(OpenScenario2Parser.COLON)
                self.state = 530
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [78]:
                    self.state = 520
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 521
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 523 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 522
                        self.behaviorWithMember()
                        self.state = 525 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 1683731646856) != 0) or _la==76 or _la==77):
                            break

                    self.state = 527
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [3, 7, 8, 11, 17, 19, 20, 21, 25, 26, 35, 39, 40, 76, 77]:
                    self.state = 529
                    self.behaviorWithMember()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [78]:
                self.state = 532
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
        self.enterRule(localctx, 74, self.RULE_behaviorWithMember)
        try:
            self.state = 539
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [3, 7, 8, 11, 19, 21, 25, 26, 39, 40, 76, 77]:
                self.enterOuterAlt(localctx, 1)
                self.state = 535
                self.modifierInvocation()
                pass
            elif token in [17]:
                self.enterOuterAlt(localctx, 2)
                self.state = 536
                self.keepConstraint()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 3)
                self.state = 537
                self.removeDefault()
                pass
            elif token in [35]:
                self.enterOuterAlt(localctx, 4)
                self.state = 538
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
        self.enterRule(localctx, 76, self.RULE_modifierInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 541
            localctx.target = self.dottedName()
            self.state = 542
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 544
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                self.state = 543
                self.argumentList()


            self.state = 546
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 547
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
        self.enterRule(localctx, 78, self.RULE_untilDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 549
            self.match(OpenScenario2Parser.UNTIL)
            self.state = 550
            self.eventSpecification()
            self.state = 551
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
        self.enterRule(localctx, 80, self.RULE_waitDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 553
            self.match(OpenScenario2Parser.WAIT)
            self.state = 554
            self.eventSpecification()
            self.state = 555
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
        self.enterRule(localctx, 82, self.RULE_emitDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 557
            self.match(OpenScenario2Parser.EMIT)
            self.state = 558
            self.identifier()
            self.state = 564
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==67:
                self.state = 559
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 561
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                    self.state = 560
                    self.argumentList()


                self.state = 563
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 566
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
        self.enterRule(localctx, 84, self.RULE_callDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 568
            self.match(OpenScenario2Parser.CALL)
            self.state = 569
            self.expression(0)
            self.state = 570
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
        self.enterRule(localctx, 86, self.RULE_argumentList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 572
            self.argument()
            self.state = 577
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,64,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 573
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 574
                    self.argument() 
                self.state = 579
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,64,self._ctx)

            self.state = 581
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==49:
                self.state = 580
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
        self.enterRule(localctx, 88, self.RULE_argument)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 586
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,66,self._ctx)
            if la_ == 1:
                self.state = 583
                localctx.name = self.identifier()
                self.state = 584
                self.match(OpenScenario2Parser.COLON)


            self.state = 588
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
        _startState = 90
        self.enterRecursionRule(localctx, 90, self.RULE_expression, _p)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 596
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [62, 63]:
                localctx = OpenScenario2Parser.UnaryContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx

                self.state = 591
                localctx.op = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==62 or _la==63):
                    localctx.op = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                self.state = 592
                self.expression(9)
                pass
            elif token in [44]:
                localctx = OpenScenario2Parser.LogicalNotContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 593
                self.match(OpenScenario2Parser.NOT)
                self.state = 594
                self.expression(5)
                pass
            elif token in [3, 7, 8, 11, 19, 21, 25, 26, 39, 40, 45, 46, 67, 69, 71, 72, 73, 74, 75, 76, 77]:
                localctx = OpenScenario2Parser.PrimaryExpressionContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 595
                self.primary()
                pass
            else:
                raise NoViableAltException(self)

            self._ctx.stop = self._input.LT(-1)
            self.state = 627
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,70,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    if self._parseListeners is not None:
                        self.triggerExitRuleEvent()
                    _prevctx = localctx
                    self.state = 625
                    self._errHandler.sync(self)
                    la_ = self._interp.adaptivePredict(self._input,69,self._ctx)
                    if la_ == 1:
                        localctx = OpenScenario2Parser.MultiplicativeContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 598
                        if not self.precpred(self._ctx, 8):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 8)")
                        self.state = 599
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(((((_la - 64)) & ~0x3f) == 0 and ((1 << (_la - 64)) & 7) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 600
                        self.expression(9)
                        pass

                    elif la_ == 2:
                        localctx = OpenScenario2Parser.AdditiveContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 601
                        if not self.precpred(self._ctx, 7):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 7)")
                        self.state = 602
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(_la==62 or _la==63):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 603
                        self.expression(8)
                        pass

                    elif la_ == 3:
                        localctx = OpenScenario2Parser.RelationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 604
                        if not self.precpred(self._ctx, 6):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 6)")
                        self.state = 605
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 567455752071938048) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 606
                        self.expression(7)
                        pass

                    elif la_ == 4:
                        localctx = OpenScenario2Parser.LogicalAndContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 607
                        if not self.precpred(self._ctx, 4):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 4)")
                        self.state = 608
                        self.match(OpenScenario2Parser.AND)
                        self.state = 609
                        self.expression(5)
                        pass

                    elif la_ == 5:
                        localctx = OpenScenario2Parser.LogicalOrContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 610
                        if not self.precpred(self._ctx, 3):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 3)")
                        self.state = 611
                        self.match(OpenScenario2Parser.OR)
                        self.state = 612
                        self.expression(4)
                        pass

                    elif la_ == 6:
                        localctx = OpenScenario2Parser.ImplicationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 613
                        if not self.precpred(self._ctx, 2):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 2)")
                        self.state = 614
                        self.match(OpenScenario2Parser.IMPLIES)
                        self.state = 615
                        self.expression(2)
                        pass

                    elif la_ == 7:
                        localctx = OpenScenario2Parser.MemberAccessContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 616
                        if not self.precpred(self._ctx, 11):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 11)")
                        self.state = 617
                        self.match(OpenScenario2Parser.DOT)
                        self.state = 618
                        self.identifier()
                        pass

                    elif la_ == 8:
                        localctx = OpenScenario2Parser.CallContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 619
                        if not self.precpred(self._ctx, 10):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 10)")
                        self.state = 620
                        self.match(OpenScenario2Parser.LPAREN)
                        self.state = 622
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                            self.state = 621
                            self.argumentList()


                        self.state = 624
                        self.match(OpenScenario2Parser.RPAREN)
                        pass

             
                self.state = 629
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
        self.enterRule(localctx, 92, self.RULE_primary)
        self._la = 0 # Token type
        try:
            self.state = 659
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,74,self._ctx)
            if la_ == 1:
                localctx = OpenScenario2Parser.PhysicalLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 630
                self.match(OpenScenario2Parser.PhysicalLiteral)
                pass

            elif la_ == 2:
                localctx = OpenScenario2Parser.NumberLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 631
                _la = self._input.LA(1)
                if not(((((_la - 71)) & ~0x3f) == 0 and ((1 << (_la - 71)) & 13) != 0)):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 3:
                localctx = OpenScenario2Parser.StringLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 632
                self.match(OpenScenario2Parser.StringLiteral)
                pass

            elif la_ == 4:
                localctx = OpenScenario2Parser.BoolLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 633
                _la = self._input.LA(1)
                if not(_la==45 or _la==46):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 5:
                localctx = OpenScenario2Parser.RangePrimaryContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 634
                self.rangeLiteral()
                pass

            elif la_ == 6:
                localctx = OpenScenario2Parser.ListLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 635
                self.match(OpenScenario2Parser.LBRACK)
                self.state = 647
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & -4611561223754348152) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 2037) != 0):
                    self.state = 636
                    self.expression(0)
                    self.state = 641
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,71,self._ctx)
                    while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                        if _alt==1:
                            self.state = 637
                            self.match(OpenScenario2Parser.COMMA)
                            self.state = 638
                            self.expression(0) 
                        self.state = 643
                        self._errHandler.sync(self)
                        _alt = self._interp.adaptivePredict(self._input,71,self._ctx)

                    self.state = 645
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if _la==49:
                        self.state = 644
                        self.match(OpenScenario2Parser.COMMA)




                self.state = 649
                self.match(OpenScenario2Parser.RBRACK)
                pass

            elif la_ == 7:
                localctx = OpenScenario2Parser.EnumValueContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 650
                localctx.enumType = self.identifier()
                self.state = 651
                self.match(OpenScenario2Parser.BANG)
                self.state = 652
                localctx.member = self.identifier()
                pass

            elif la_ == 8:
                localctx = OpenScenario2Parser.NamePrimaryContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 654
                self.identifier()
                pass

            elif la_ == 9:
                localctx = OpenScenario2Parser.ParenthesisedContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 655
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 656
                self.expression(0)
                self.state = 657
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
        self.enterRule(localctx, 94, self.RULE_rangeLiteral)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 661
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 662
            localctx.low = self.expression(0)
            self.state = 663
            self.match(OpenScenario2Parser.DOUBLEDOT)
            self.state = 664
            localctx.high = self.expression(0)
            self.state = 665
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 667
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,75,self._ctx)
            if la_ == 1:
                self.state = 666
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
        self.enterRule(localctx, 96, self.RULE_dottedName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 669
            self.identifier()
            self.state = 674
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==48:
                self.state = 670
                self.match(OpenScenario2Parser.DOT)
                self.state = 671
                self.identifier()
                self.state = 676
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

        def TYPE(self):
            return self.getToken(OpenScenario2Parser.TYPE, 0)

        def UNIT(self):
            return self.getToken(OpenScenario2Parser.UNIT, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_identifier

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIdentifier" ):
                return visitor.visitIdentifier(self)
            else:
                return visitor.visitChildren(self)




    def identifier(self):

        localctx = OpenScenario2Parser.IdentifierContext(self, self._ctx, self.state)
        self.enterRule(localctx, 98, self.RULE_identifier)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 677
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 1649370728840) != 0) or _la==76 or _la==77):
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
        self._predicates[45] = self.expression_sempred
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
         




