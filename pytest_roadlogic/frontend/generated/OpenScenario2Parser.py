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
        4,1,88,751,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,2,43,7,43,2,44,7,44,2,45,7,45,2,46,
        7,46,2,47,7,47,2,48,7,48,2,49,7,49,2,50,7,50,2,51,7,51,1,0,1,0,1,
        0,5,0,108,8,0,10,0,12,0,111,9,0,1,0,1,0,1,1,1,1,1,1,3,1,118,8,1,
        1,1,1,1,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,3,2,133,8,2,
        1,3,1,3,1,3,3,3,138,8,3,1,3,1,3,1,3,1,3,4,3,144,8,3,11,3,12,3,145,
        1,3,1,3,1,3,3,3,151,8,3,1,4,1,4,1,4,3,4,156,8,4,1,4,1,4,1,5,1,5,
        1,5,1,5,1,5,1,5,3,5,166,8,5,1,6,1,6,1,6,3,6,171,8,6,1,6,1,6,1,6,
        1,6,4,6,177,8,6,11,6,12,6,178,1,6,1,6,1,6,3,6,184,8,6,1,7,1,7,1,
        7,3,7,189,8,7,1,7,1,7,1,7,1,7,4,7,195,8,7,11,7,12,7,196,1,7,1,7,
        1,7,3,7,202,8,7,1,8,1,8,1,8,1,8,1,8,1,8,1,8,3,8,211,8,8,1,9,1,9,
        1,9,1,9,1,9,1,9,1,9,1,9,1,9,1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,
        10,1,10,1,10,1,10,1,11,1,11,1,11,1,11,1,11,1,11,1,11,5,11,240,8,
        11,10,11,12,11,243,9,11,1,11,3,11,246,8,11,1,11,1,11,1,11,1,12,1,
        12,1,12,3,12,254,8,12,1,13,1,13,1,13,1,14,1,14,1,14,1,14,1,14,1,
        14,4,14,265,8,14,11,14,12,14,266,1,14,1,14,1,14,1,14,1,14,1,14,1,
        14,1,14,1,14,5,14,278,8,14,10,14,12,14,281,9,14,1,14,3,14,284,8,
        14,1,14,1,14,1,14,3,14,289,8,14,1,15,1,15,1,15,1,15,3,15,295,8,15,
        1,16,1,16,1,16,1,16,3,16,301,8,16,1,16,1,16,1,16,1,16,4,16,307,8,
        16,11,16,12,16,308,1,16,1,16,1,16,3,16,314,8,16,1,17,1,17,1,17,1,
        17,1,17,1,17,5,17,322,8,17,10,17,12,17,325,9,17,3,17,327,8,17,1,
        17,1,17,1,18,1,18,1,18,1,18,5,18,335,8,18,10,18,12,18,338,9,18,1,
        18,1,18,1,19,1,19,1,19,1,19,1,19,1,19,1,19,1,19,1,19,1,19,3,19,352,
        8,19,1,20,1,20,1,20,5,20,357,8,20,10,20,12,20,360,9,20,1,20,1,20,
        1,20,1,20,3,20,366,8,20,1,20,1,20,1,20,1,20,1,20,4,20,373,8,20,11,
        20,12,20,374,1,20,1,20,1,20,3,20,380,8,20,1,20,3,20,383,8,20,1,21,
        1,21,3,21,387,8,21,1,22,1,22,1,22,1,22,3,22,393,8,22,1,23,1,23,1,
        23,1,23,5,23,399,8,23,10,23,12,23,402,9,23,1,23,1,23,3,23,406,8,
        23,1,23,1,23,1,23,3,23,411,8,23,3,23,413,8,23,1,23,1,23,1,24,1,24,
        1,24,1,24,1,24,1,24,1,24,3,24,424,8,24,1,24,1,24,1,25,1,25,1,25,
        3,25,431,8,25,1,25,1,25,1,25,1,25,1,26,1,26,1,26,1,26,1,26,1,26,
        1,27,1,27,1,27,1,27,3,27,447,8,27,1,27,3,27,450,8,27,1,27,1,27,3,
        27,454,8,27,1,27,1,27,1,28,1,28,1,28,1,28,3,28,462,8,28,1,28,1,28,
        3,28,466,8,28,1,28,3,28,469,8,28,1,29,1,29,1,29,1,29,3,29,475,8,
        29,1,29,1,29,1,29,3,29,480,8,29,1,29,1,29,3,29,484,8,29,1,29,1,29,
        1,29,1,29,1,29,1,29,3,29,492,8,29,1,29,1,29,1,30,1,30,1,30,5,30,
        499,8,30,10,30,12,30,502,9,30,1,31,1,31,1,31,1,31,1,31,3,31,509,
        8,31,1,32,1,32,1,32,3,32,514,8,32,1,32,1,32,1,32,1,33,1,33,1,33,
        1,33,1,33,1,33,4,33,525,8,33,11,33,12,33,526,1,33,1,33,1,34,1,34,
        1,34,1,35,1,35,1,35,3,35,537,8,35,1,35,1,35,1,35,1,35,1,35,3,35,
        544,8,35,1,36,1,36,1,36,3,36,549,8,36,1,36,3,36,552,8,36,1,36,1,
        36,1,36,1,36,4,36,558,8,36,11,36,12,36,559,1,36,1,36,1,37,1,37,1,
        38,1,38,1,38,3,38,569,8,38,1,38,1,38,1,38,1,38,1,38,1,38,4,38,577,
        8,38,11,38,12,38,578,1,38,1,38,1,38,3,38,584,8,38,1,38,3,38,587,
        8,38,1,39,1,39,1,39,1,39,3,39,593,8,39,1,40,1,40,1,40,3,40,598,8,
        40,1,40,1,40,1,40,1,41,1,41,1,41,1,41,1,42,1,42,1,42,1,42,1,43,1,
        43,1,43,1,43,3,43,615,8,43,1,43,3,43,618,8,43,1,43,1,43,1,44,1,44,
        1,44,1,44,1,45,1,45,1,45,5,45,629,8,45,10,45,12,45,632,9,45,1,45,
        3,45,635,8,45,1,46,1,46,1,46,3,46,640,8,46,1,46,1,46,1,47,1,47,1,
        47,1,47,1,47,1,47,3,47,650,8,47,1,47,1,47,1,47,1,47,1,47,1,47,1,
        47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,
        47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,
        47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,1,47,3,47,694,8,47,1,
        47,5,47,697,8,47,10,47,12,47,700,9,47,1,48,1,48,1,48,1,48,1,48,1,
        48,1,48,1,48,1,48,5,48,711,8,48,10,48,12,48,714,9,48,1,48,3,48,717,
        8,48,3,48,719,8,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,
        1,48,3,48,731,8,48,1,49,1,49,1,49,1,49,1,49,1,49,3,49,739,8,49,1,
        50,1,50,1,50,5,50,744,8,50,10,50,12,50,747,9,50,1,51,1,51,1,51,0,
        1,94,52,0,2,4,6,8,10,12,14,16,18,20,22,24,26,28,30,32,34,36,38,40,
        42,44,46,48,50,52,54,56,58,60,62,64,66,68,70,72,74,76,78,80,82,84,
        86,88,90,92,94,96,98,100,102,0,12,1,0,2,3,2,0,76,76,79,79,1,0,18,
        19,1,0,27,28,1,0,31,33,1,0,67,68,1,0,69,71,2,0,41,41,57,62,2,0,22,
        22,47,47,2,0,76,76,78,79,1,0,45,46,7,0,1,15,19,19,21,21,25,26,39,
        40,47,50,81,82,829,0,109,1,0,0,0,2,114,1,0,0,0,4,132,1,0,0,0,6,134,
        1,0,0,0,8,155,1,0,0,0,10,159,1,0,0,0,12,167,1,0,0,0,14,185,1,0,0,
        0,16,210,1,0,0,0,18,212,1,0,0,0,20,221,1,0,0,0,22,232,1,0,0,0,24,
        250,1,0,0,0,26,255,1,0,0,0,28,288,1,0,0,0,30,294,1,0,0,0,32,296,
        1,0,0,0,34,315,1,0,0,0,36,330,1,0,0,0,38,351,1,0,0,0,40,353,1,0,
        0,0,42,386,1,0,0,0,44,392,1,0,0,0,46,394,1,0,0,0,48,416,1,0,0,0,
        50,427,1,0,0,0,52,436,1,0,0,0,54,442,1,0,0,0,56,468,1,0,0,0,58,470,
        1,0,0,0,60,495,1,0,0,0,62,503,1,0,0,0,64,510,1,0,0,0,66,518,1,0,
        0,0,68,530,1,0,0,0,70,536,1,0,0,0,72,545,1,0,0,0,74,563,1,0,0,0,
        76,565,1,0,0,0,78,592,1,0,0,0,80,594,1,0,0,0,82,602,1,0,0,0,84,606,
        1,0,0,0,86,610,1,0,0,0,88,621,1,0,0,0,90,625,1,0,0,0,92,639,1,0,
        0,0,94,649,1,0,0,0,96,730,1,0,0,0,98,732,1,0,0,0,100,740,1,0,0,0,
        102,748,1,0,0,0,104,108,3,2,1,0,105,108,3,4,2,0,106,108,5,83,0,0,
        107,104,1,0,0,0,107,105,1,0,0,0,107,106,1,0,0,0,108,111,1,0,0,0,
        109,107,1,0,0,0,109,110,1,0,0,0,110,112,1,0,0,0,111,109,1,0,0,0,
        112,113,5,0,0,1,113,1,1,0,0,0,114,117,5,1,0,0,115,118,5,80,0,0,116,
        118,3,100,50,0,117,115,1,0,0,0,117,116,1,0,0,0,118,119,1,0,0,0,119,
        120,5,83,0,0,120,3,1,0,0,0,121,133,3,6,3,0,122,133,3,18,9,0,123,
        133,3,20,10,0,124,133,3,12,6,0,125,133,3,14,7,0,126,133,3,22,11,
        0,127,133,3,26,13,0,128,133,3,28,14,0,129,133,3,32,16,0,130,133,
        3,34,17,0,131,133,3,36,18,0,132,121,1,0,0,0,132,122,1,0,0,0,132,
        123,1,0,0,0,132,124,1,0,0,0,132,125,1,0,0,0,132,126,1,0,0,0,132,
        127,1,0,0,0,132,128,1,0,0,0,132,129,1,0,0,0,132,130,1,0,0,0,132,
        131,1,0,0,0,133,5,1,0,0,0,134,135,7,0,0,0,135,137,3,8,4,0,136,138,
        3,10,5,0,137,136,1,0,0,0,137,138,1,0,0,0,138,150,1,0,0,0,139,140,
        5,54,0,0,140,141,5,83,0,0,141,143,5,87,0,0,142,144,3,38,19,0,143,
        142,1,0,0,0,144,145,1,0,0,0,145,143,1,0,0,0,145,146,1,0,0,0,146,
        147,1,0,0,0,147,148,5,88,0,0,148,151,1,0,0,0,149,151,5,83,0,0,150,
        139,1,0,0,0,150,149,1,0,0,0,151,7,1,0,0,0,152,153,3,102,51,0,153,
        154,5,52,0,0,154,156,1,0,0,0,155,152,1,0,0,0,155,156,1,0,0,0,156,
        157,1,0,0,0,157,158,3,102,51,0,158,9,1,0,0,0,159,160,5,15,0,0,160,
        165,3,8,4,0,161,162,5,72,0,0,162,163,3,94,47,0,163,164,5,73,0,0,
        164,166,1,0,0,0,165,161,1,0,0,0,165,166,1,0,0,0,166,11,1,0,0,0,167,
        168,5,4,0,0,168,170,3,102,51,0,169,171,3,10,5,0,170,169,1,0,0,0,
        170,171,1,0,0,0,171,183,1,0,0,0,172,173,5,54,0,0,173,174,5,83,0,
        0,174,176,5,87,0,0,175,177,3,16,8,0,176,175,1,0,0,0,177,178,1,0,
        0,0,178,176,1,0,0,0,178,179,1,0,0,0,179,180,1,0,0,0,180,181,5,88,
        0,0,181,184,1,0,0,0,182,184,5,83,0,0,183,172,1,0,0,0,183,182,1,0,
        0,0,184,13,1,0,0,0,185,186,5,5,0,0,186,188,3,102,51,0,187,189,3,
        10,5,0,188,187,1,0,0,0,188,189,1,0,0,0,189,201,1,0,0,0,190,191,5,
        54,0,0,191,192,5,83,0,0,192,194,5,87,0,0,193,195,3,16,8,0,194,193,
        1,0,0,0,195,196,1,0,0,0,196,194,1,0,0,0,196,197,1,0,0,0,197,198,
        1,0,0,0,198,199,5,88,0,0,199,202,1,0,0,0,200,202,5,83,0,0,201,190,
        1,0,0,0,201,200,1,0,0,0,202,15,1,0,0,0,203,211,3,40,20,0,204,211,
        3,46,23,0,205,211,3,50,25,0,206,211,3,52,26,0,207,211,3,54,27,0,
        208,211,3,58,29,0,209,211,3,64,32,0,210,203,1,0,0,0,210,204,1,0,
        0,0,210,205,1,0,0,0,210,206,1,0,0,0,210,207,1,0,0,0,210,208,1,0,
        0,0,210,209,1,0,0,0,211,17,1,0,0,0,212,213,5,7,0,0,213,214,3,102,
        51,0,214,215,5,22,0,0,215,216,3,102,51,0,216,217,5,72,0,0,217,218,
        3,90,45,0,218,219,5,73,0,0,219,220,5,83,0,0,220,19,1,0,0,0,221,222,
        5,8,0,0,222,223,3,102,51,0,223,224,5,40,0,0,224,225,3,102,51,0,225,
        226,5,22,0,0,226,227,3,102,51,0,227,228,5,72,0,0,228,229,3,90,45,
        0,229,230,5,73,0,0,230,231,5,83,0,0,231,21,1,0,0,0,232,233,5,6,0,
        0,233,234,3,102,51,0,234,235,5,54,0,0,235,236,5,74,0,0,236,241,3,
        24,12,0,237,238,5,53,0,0,238,240,3,24,12,0,239,237,1,0,0,0,240,243,
        1,0,0,0,241,239,1,0,0,0,241,242,1,0,0,0,242,245,1,0,0,0,243,241,
        1,0,0,0,244,246,5,53,0,0,245,244,1,0,0,0,245,246,1,0,0,0,246,247,
        1,0,0,0,247,248,5,75,0,0,248,249,5,83,0,0,249,23,1,0,0,0,250,253,
        3,102,51,0,251,252,5,63,0,0,252,254,7,1,0,0,253,251,1,0,0,0,253,
        254,1,0,0,0,254,25,1,0,0,0,255,256,5,9,0,0,256,257,3,40,20,0,257,
        27,1,0,0,0,258,259,5,10,0,0,259,260,3,8,4,0,260,261,5,54,0,0,261,
        262,5,83,0,0,262,264,5,87,0,0,263,265,3,30,15,0,264,263,1,0,0,0,
        265,266,1,0,0,0,266,264,1,0,0,0,266,267,1,0,0,0,267,268,1,0,0,0,
        268,269,5,88,0,0,269,289,1,0,0,0,270,271,5,10,0,0,271,272,3,8,4,
        0,272,273,5,54,0,0,273,274,5,74,0,0,274,279,3,24,12,0,275,276,5,
        53,0,0,276,278,3,24,12,0,277,275,1,0,0,0,278,281,1,0,0,0,279,277,
        1,0,0,0,279,280,1,0,0,0,280,283,1,0,0,0,281,279,1,0,0,0,282,284,
        5,53,0,0,283,282,1,0,0,0,283,284,1,0,0,0,284,285,1,0,0,0,285,286,
        5,75,0,0,286,287,5,83,0,0,287,289,1,0,0,0,288,258,1,0,0,0,288,270,
        1,0,0,0,289,29,1,0,0,0,290,295,3,38,19,0,291,292,3,24,12,0,292,293,
        5,83,0,0,293,295,1,0,0,0,294,290,1,0,0,0,294,291,1,0,0,0,295,31,
        1,0,0,0,296,297,5,11,0,0,297,300,3,8,4,0,298,299,5,40,0,0,299,301,
        3,102,51,0,300,298,1,0,0,0,300,301,1,0,0,0,301,313,1,0,0,0,302,303,
        5,54,0,0,303,304,5,83,0,0,304,306,5,87,0,0,305,307,3,38,19,0,306,
        305,1,0,0,0,307,308,1,0,0,0,308,306,1,0,0,0,308,309,1,0,0,0,309,
        310,1,0,0,0,310,311,5,88,0,0,311,314,1,0,0,0,312,314,5,83,0,0,313,
        302,1,0,0,0,313,312,1,0,0,0,314,33,1,0,0,0,315,316,5,12,0,0,316,
        326,3,102,51,0,317,318,5,13,0,0,318,323,3,102,51,0,319,320,5,53,
        0,0,320,322,3,102,51,0,321,319,1,0,0,0,322,325,1,0,0,0,323,321,1,
        0,0,0,323,324,1,0,0,0,324,327,1,0,0,0,325,323,1,0,0,0,326,317,1,
        0,0,0,326,327,1,0,0,0,327,328,1,0,0,0,328,329,5,83,0,0,329,35,1,
        0,0,0,330,331,5,14,0,0,331,336,3,100,50,0,332,333,5,53,0,0,333,335,
        3,100,50,0,334,332,1,0,0,0,335,338,1,0,0,0,336,334,1,0,0,0,336,337,
        1,0,0,0,337,339,1,0,0,0,338,336,1,0,0,0,339,340,5,83,0,0,340,37,
        1,0,0,0,341,352,3,40,20,0,342,352,3,46,23,0,343,352,3,50,25,0,344,
        352,3,52,26,0,345,352,3,54,27,0,346,352,3,58,29,0,347,352,3,64,32,
        0,348,352,3,66,33,0,349,352,3,68,34,0,350,352,3,80,40,0,351,341,
        1,0,0,0,351,342,1,0,0,0,351,343,1,0,0,0,351,344,1,0,0,0,351,345,
        1,0,0,0,351,346,1,0,0,0,351,347,1,0,0,0,351,348,1,0,0,0,351,349,
        1,0,0,0,351,350,1,0,0,0,352,39,1,0,0,0,353,358,3,102,51,0,354,355,
        5,53,0,0,355,357,3,102,51,0,356,354,1,0,0,0,357,360,1,0,0,0,358,
        356,1,0,0,0,358,359,1,0,0,0,359,361,1,0,0,0,360,358,1,0,0,0,361,
        362,5,54,0,0,362,365,3,44,22,0,363,364,5,63,0,0,364,366,3,94,47,
        0,365,363,1,0,0,0,365,366,1,0,0,0,366,382,1,0,0,0,367,368,5,34,0,
        0,368,379,5,54,0,0,369,370,5,83,0,0,370,372,5,87,0,0,371,373,3,42,
        21,0,372,371,1,0,0,0,373,374,1,0,0,0,374,372,1,0,0,0,374,375,1,0,
        0,0,375,376,1,0,0,0,376,377,5,88,0,0,377,380,1,0,0,0,378,380,3,42,
        21,0,379,369,1,0,0,0,379,378,1,0,0,0,380,383,1,0,0,0,381,383,5,83,
        0,0,382,367,1,0,0,0,382,381,1,0,0,0,383,41,1,0,0,0,384,387,3,50,
        25,0,385,387,3,52,26,0,386,384,1,0,0,0,386,385,1,0,0,0,387,43,1,
        0,0,0,388,389,5,39,0,0,389,390,5,40,0,0,390,393,3,102,51,0,391,393,
        3,102,51,0,392,388,1,0,0,0,392,391,1,0,0,0,393,45,1,0,0,0,394,395,
        5,16,0,0,395,400,3,102,51,0,396,397,5,53,0,0,397,399,3,102,51,0,
        398,396,1,0,0,0,399,402,1,0,0,0,400,398,1,0,0,0,400,401,1,0,0,0,
        401,405,1,0,0,0,402,400,1,0,0,0,403,404,5,54,0,0,404,406,3,44,22,
        0,405,403,1,0,0,0,405,406,1,0,0,0,406,412,1,0,0,0,407,410,5,63,0,
        0,408,411,3,48,24,0,409,411,3,94,47,0,410,408,1,0,0,0,410,409,1,
        0,0,0,411,413,1,0,0,0,412,407,1,0,0,0,412,413,1,0,0,0,413,414,1,
        0,0,0,414,415,5,83,0,0,415,47,1,0,0,0,416,417,5,50,0,0,417,418,5,
        72,0,0,418,419,3,94,47,0,419,420,5,53,0,0,420,423,3,56,28,0,421,
        422,5,53,0,0,422,424,3,94,47,0,423,421,1,0,0,0,423,424,1,0,0,0,424,
        425,1,0,0,0,425,426,5,73,0,0,426,49,1,0,0,0,427,428,5,17,0,0,428,
        430,5,72,0,0,429,431,7,2,0,0,430,429,1,0,0,0,430,431,1,0,0,0,431,
        432,1,0,0,0,432,433,3,94,47,0,433,434,5,73,0,0,434,435,5,83,0,0,
        435,51,1,0,0,0,436,437,5,20,0,0,437,438,5,72,0,0,438,439,3,94,47,
        0,439,440,5,73,0,0,440,441,5,83,0,0,441,53,1,0,0,0,442,443,5,21,
        0,0,443,449,3,102,51,0,444,446,5,72,0,0,445,447,3,60,30,0,446,445,
        1,0,0,0,446,447,1,0,0,0,447,448,1,0,0,0,448,450,5,73,0,0,449,444,
        1,0,0,0,449,450,1,0,0,0,450,453,1,0,0,0,451,452,5,22,0,0,452,454,
        3,56,28,0,453,451,1,0,0,0,453,454,1,0,0,0,454,455,1,0,0,0,455,456,
        5,83,0,0,456,55,1,0,0,0,457,458,5,66,0,0,458,461,3,100,50,0,459,
        460,5,47,0,0,460,462,3,102,51,0,461,459,1,0,0,0,461,462,1,0,0,0,
        462,465,1,0,0,0,463,464,5,23,0,0,464,466,3,94,47,0,465,463,1,0,0,
        0,465,466,1,0,0,0,466,469,1,0,0,0,467,469,3,94,47,0,468,457,1,0,
        0,0,468,467,1,0,0,0,469,57,1,0,0,0,470,471,5,24,0,0,471,472,3,102,
        51,0,472,474,5,72,0,0,473,475,3,60,30,0,474,473,1,0,0,0,474,475,
        1,0,0,0,475,476,1,0,0,0,476,479,5,73,0,0,477,478,5,55,0,0,478,480,
        3,44,22,0,479,477,1,0,0,0,479,480,1,0,0,0,480,481,1,0,0,0,481,483,
        5,22,0,0,482,484,5,48,0,0,483,482,1,0,0,0,483,484,1,0,0,0,484,491,
        1,0,0,0,485,486,5,49,0,0,486,492,3,94,47,0,487,492,5,26,0,0,488,
        489,5,25,0,0,489,492,3,94,47,0,490,492,3,94,47,0,491,485,1,0,0,0,
        491,487,1,0,0,0,491,488,1,0,0,0,491,490,1,0,0,0,492,493,1,0,0,0,
        493,494,5,83,0,0,494,59,1,0,0,0,495,500,3,62,31,0,496,497,5,53,0,
        0,497,499,3,62,31,0,498,496,1,0,0,0,499,502,1,0,0,0,500,498,1,0,
        0,0,500,501,1,0,0,0,501,61,1,0,0,0,502,500,1,0,0,0,503,504,3,102,
        51,0,504,505,5,54,0,0,505,508,3,44,22,0,506,507,5,63,0,0,507,509,
        3,94,47,0,508,506,1,0,0,0,508,509,1,0,0,0,509,63,1,0,0,0,510,511,
        7,3,0,0,511,513,5,72,0,0,512,514,3,90,45,0,513,512,1,0,0,0,513,514,
        1,0,0,0,514,515,1,0,0,0,515,516,5,73,0,0,516,517,5,83,0,0,517,65,
        1,0,0,0,518,519,5,29,0,0,519,520,3,56,28,0,520,521,5,54,0,0,521,
        522,5,83,0,0,522,524,5,87,0,0,523,525,3,70,35,0,524,523,1,0,0,0,
        525,526,1,0,0,0,526,524,1,0,0,0,526,527,1,0,0,0,527,528,1,0,0,0,
        528,529,5,88,0,0,529,67,1,0,0,0,530,531,5,30,0,0,531,532,3,70,35,
        0,532,69,1,0,0,0,533,534,3,102,51,0,534,535,5,54,0,0,535,537,1,0,
        0,0,536,533,1,0,0,0,536,537,1,0,0,0,537,543,1,0,0,0,538,544,3,72,
        36,0,539,544,3,76,38,0,540,544,3,84,42,0,541,544,3,86,43,0,542,544,
        3,88,44,0,543,538,1,0,0,0,543,539,1,0,0,0,543,540,1,0,0,0,543,541,
        1,0,0,0,543,542,1,0,0,0,544,71,1,0,0,0,545,551,3,74,37,0,546,548,
        5,72,0,0,547,549,3,90,45,0,548,547,1,0,0,0,548,549,1,0,0,0,549,550,
        1,0,0,0,550,552,5,73,0,0,551,546,1,0,0,0,551,552,1,0,0,0,552,553,
        1,0,0,0,553,554,5,54,0,0,554,555,5,83,0,0,555,557,5,87,0,0,556,558,
        3,70,35,0,557,556,1,0,0,0,558,559,1,0,0,0,559,557,1,0,0,0,559,560,
        1,0,0,0,560,561,1,0,0,0,561,562,5,88,0,0,562,73,1,0,0,0,563,564,
        7,4,0,0,564,75,1,0,0,0,565,566,3,100,50,0,566,568,5,72,0,0,567,569,
        3,90,45,0,568,567,1,0,0,0,568,569,1,0,0,0,569,570,1,0,0,0,570,586,
        5,73,0,0,571,572,5,34,0,0,572,583,5,54,0,0,573,574,5,83,0,0,574,
        576,5,87,0,0,575,577,3,78,39,0,576,575,1,0,0,0,577,578,1,0,0,0,578,
        576,1,0,0,0,578,579,1,0,0,0,579,580,1,0,0,0,580,581,5,88,0,0,581,
        584,1,0,0,0,582,584,3,78,39,0,583,573,1,0,0,0,583,582,1,0,0,0,584,
        587,1,0,0,0,585,587,5,83,0,0,586,571,1,0,0,0,586,585,1,0,0,0,587,
        77,1,0,0,0,588,593,3,80,40,0,589,593,3,50,25,0,590,593,3,52,26,0,
        591,593,3,82,41,0,592,588,1,0,0,0,592,589,1,0,0,0,592,590,1,0,0,
        0,592,591,1,0,0,0,593,79,1,0,0,0,594,595,3,100,50,0,595,597,5,72,
        0,0,596,598,3,90,45,0,597,596,1,0,0,0,597,598,1,0,0,0,598,599,1,
        0,0,0,599,600,5,73,0,0,600,601,5,83,0,0,601,81,1,0,0,0,602,603,5,
        35,0,0,603,604,3,56,28,0,604,605,5,83,0,0,605,83,1,0,0,0,606,607,
        5,36,0,0,607,608,3,56,28,0,608,609,5,83,0,0,609,85,1,0,0,0,610,611,
        5,37,0,0,611,617,3,102,51,0,612,614,5,72,0,0,613,615,3,90,45,0,614,
        613,1,0,0,0,614,615,1,0,0,0,615,616,1,0,0,0,616,618,5,73,0,0,617,
        612,1,0,0,0,617,618,1,0,0,0,618,619,1,0,0,0,619,620,5,83,0,0,620,
        87,1,0,0,0,621,622,5,38,0,0,622,623,3,94,47,0,623,624,5,83,0,0,624,
        89,1,0,0,0,625,630,3,92,46,0,626,627,5,53,0,0,627,629,3,92,46,0,
        628,626,1,0,0,0,629,632,1,0,0,0,630,628,1,0,0,0,630,631,1,0,0,0,
        631,634,1,0,0,0,632,630,1,0,0,0,633,635,5,53,0,0,634,633,1,0,0,0,
        634,635,1,0,0,0,635,91,1,0,0,0,636,637,3,102,51,0,637,638,5,54,0,
        0,638,640,1,0,0,0,639,636,1,0,0,0,639,640,1,0,0,0,640,641,1,0,0,
        0,641,642,3,94,47,0,642,93,1,0,0,0,643,644,6,47,-1,0,644,645,7,5,
        0,0,645,650,3,94,47,10,646,647,5,44,0,0,647,650,3,94,47,6,648,650,
        3,96,48,0,649,643,1,0,0,0,649,646,1,0,0,0,649,648,1,0,0,0,650,698,
        1,0,0,0,651,652,10,9,0,0,652,653,7,6,0,0,653,697,3,94,47,10,654,
        655,10,8,0,0,655,656,7,5,0,0,656,697,3,94,47,9,657,658,10,7,0,0,
        658,659,7,7,0,0,659,697,3,94,47,8,660,661,10,5,0,0,661,662,5,42,
        0,0,662,697,3,94,47,6,663,664,10,4,0,0,664,665,5,43,0,0,665,697,
        3,94,47,5,666,667,10,3,0,0,667,668,5,56,0,0,668,697,3,94,47,3,669,
        670,10,2,0,0,670,671,5,65,0,0,671,672,3,94,47,0,672,673,5,54,0,0,
        673,674,3,94,47,2,674,697,1,0,0,0,675,676,10,14,0,0,676,677,5,52,
        0,0,677,678,7,8,0,0,678,679,5,72,0,0,679,680,3,44,22,0,680,681,5,
        73,0,0,681,697,1,0,0,0,682,683,10,13,0,0,683,684,5,52,0,0,684,697,
        3,102,51,0,685,686,10,12,0,0,686,687,5,74,0,0,687,688,3,94,47,0,
        688,689,5,75,0,0,689,697,1,0,0,0,690,691,10,11,0,0,691,693,5,72,
        0,0,692,694,3,90,45,0,693,692,1,0,0,0,693,694,1,0,0,0,694,695,1,
        0,0,0,695,697,5,73,0,0,696,651,1,0,0,0,696,654,1,0,0,0,696,657,1,
        0,0,0,696,660,1,0,0,0,696,663,1,0,0,0,696,666,1,0,0,0,696,669,1,
        0,0,0,696,675,1,0,0,0,696,682,1,0,0,0,696,685,1,0,0,0,696,690,1,
        0,0,0,697,700,1,0,0,0,698,696,1,0,0,0,698,699,1,0,0,0,699,95,1,0,
        0,0,700,698,1,0,0,0,701,731,5,77,0,0,702,731,7,9,0,0,703,731,5,80,
        0,0,704,731,7,10,0,0,705,731,3,98,49,0,706,718,5,74,0,0,707,712,
        3,94,47,0,708,709,5,53,0,0,709,711,3,94,47,0,710,708,1,0,0,0,711,
        714,1,0,0,0,712,710,1,0,0,0,712,713,1,0,0,0,713,716,1,0,0,0,714,
        712,1,0,0,0,715,717,5,53,0,0,716,715,1,0,0,0,716,717,1,0,0,0,717,
        719,1,0,0,0,718,707,1,0,0,0,718,719,1,0,0,0,719,720,1,0,0,0,720,
        731,5,75,0,0,721,722,3,102,51,0,722,723,5,64,0,0,723,724,3,102,51,
        0,724,731,1,0,0,0,725,731,3,102,51,0,726,727,5,72,0,0,727,728,3,
        94,47,0,728,729,5,73,0,0,729,731,1,0,0,0,730,701,1,0,0,0,730,702,
        1,0,0,0,730,703,1,0,0,0,730,704,1,0,0,0,730,705,1,0,0,0,730,706,
        1,0,0,0,730,721,1,0,0,0,730,725,1,0,0,0,730,726,1,0,0,0,731,97,1,
        0,0,0,732,733,5,74,0,0,733,734,3,94,47,0,734,735,5,51,0,0,735,736,
        3,94,47,0,736,738,5,75,0,0,737,739,5,81,0,0,738,737,1,0,0,0,738,
        739,1,0,0,0,739,99,1,0,0,0,740,745,3,102,51,0,741,742,5,52,0,0,742,
        744,3,102,51,0,743,741,1,0,0,0,744,747,1,0,0,0,745,743,1,0,0,0,745,
        746,1,0,0,0,746,101,1,0,0,0,747,745,1,0,0,0,748,749,7,11,0,0,749,
        103,1,0,0,0,84,107,109,117,132,137,145,150,155,165,170,178,183,188,
        196,201,210,241,245,253,266,279,283,288,294,300,308,313,323,326,
        336,351,358,365,374,379,382,386,392,400,405,410,412,423,430,446,
        449,453,461,465,468,474,479,483,491,500,508,513,526,536,543,548,
        551,559,568,578,583,586,592,597,614,617,630,634,639,649,693,696,
        698,712,716,718,730,738,745
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
                     "'or'", "'not'", "'true'", "'false'", "'as'", "'only'", 
                     "'expression'", "'sample'", "'..'", "'.'", "','", "':'", 
                     "'->'", "'=>'", "'=='", "'!='", "'<='", "'>='", "'<'", 
                     "'>'", "'='", "'!'", "'?'", "'@'", "'+'", "'-'", "'*'", 
                     "'/'", "'%'", "'('", "')'", "'['", "']'" ]

    symbolicNames = [ "<INVALID>", "IMPORT", "SCENARIO", "ACTION", "ACTOR", 
                      "STRUCT", "ENUM", "TYPE", "UNIT", "GLOBAL", "EXTEND", 
                      "MODIFIER", "NAMESPACE", "USE", "EXPORT", "INHERITS", 
                      "VAR", "KEEP", "DEFAULT", "HARD", "REMOVE_DEFAULT", 
                      "EVENT", "IS", "IF", "DEF", "EXTERNAL", "UNDEFINED", 
                      "COVER", "RECORD", "ON", "DO", "SERIAL", "PARALLEL", 
                      "ONE_OF", "WITH", "UNTIL", "WAIT", "EMIT", "CALL", 
                      "LIST", "OF", "IN", "AND", "OR", "NOT", "TRUE", "FALSE", 
                      "AS", "ONLY", "EXPRESSION", "SAMPLE", "DOUBLEDOT", 
                      "DOT", "COMMA", "COLON", "ARROW", "IMPLIES", "EQ", 
                      "NE", "LE", "GE", "LT", "GT", "ASSIGN", "BANG", "QUESTION", 
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
    RULE_extensionMember = 15
    RULE_modifierDeclaration = 16
    RULE_namespaceStatement = 17
    RULE_exportStatement = 18
    RULE_scenarioMember = 19
    RULE_fieldDeclaration = 20
    RULE_fieldConstraint = 21
    RULE_typeDeclarator = 22
    RULE_variableDeclaration = 23
    RULE_sampleExpression = 24
    RULE_keepConstraint = 25
    RULE_removeDefault = 26
    RULE_eventDeclaration = 27
    RULE_eventSpecification = 28
    RULE_methodDeclaration = 29
    RULE_parameterList = 30
    RULE_parameter = 31
    RULE_coverageDeclaration = 32
    RULE_onDirective = 33
    RULE_doDirective = 34
    RULE_doMember = 35
    RULE_composition = 36
    RULE_compositionOperator = 37
    RULE_behaviorInvocation = 38
    RULE_behaviorWithMember = 39
    RULE_modifierInvocation = 40
    RULE_untilDirective = 41
    RULE_waitDirective = 42
    RULE_emitDirective = 43
    RULE_callDirective = 44
    RULE_argumentList = 45
    RULE_argument = 46
    RULE_expression = 47
    RULE_primary = 48
    RULE_rangeLiteral = 49
    RULE_dottedName = 50
    RULE_identifier = 51

    ruleNames =  [ "oscFile", "importStatement", "declaration", "scenarioDeclaration", 
                   "behaviorName", "inheritance", "actorDeclaration", "structDeclaration", 
                   "structMember", "physicalTypeDeclaration", "unitDeclaration", 
                   "enumDeclaration", "enumMember", "globalDeclaration", 
                   "extendDeclaration", "extensionMember", "modifierDeclaration", 
                   "namespaceStatement", "exportStatement", "scenarioMember", 
                   "fieldDeclaration", "fieldConstraint", "typeDeclarator", 
                   "variableDeclaration", "sampleExpression", "keepConstraint", 
                   "removeDefault", "eventDeclaration", "eventSpecification", 
                   "methodDeclaration", "parameterList", "parameter", "coverageDeclaration", 
                   "onDirective", "doDirective", "doMember", "composition", 
                   "compositionOperator", "behaviorInvocation", "behaviorWithMember", 
                   "modifierInvocation", "untilDirective", "waitDirective", 
                   "emitDirective", "callDirective", "argumentList", "argument", 
                   "expression", "primary", "rangeLiteral", "dottedName", 
                   "identifier" ]

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
    AS=47
    ONLY=48
    EXPRESSION=49
    SAMPLE=50
    DOUBLEDOT=51
    DOT=52
    COMMA=53
    COLON=54
    ARROW=55
    IMPLIES=56
    EQ=57
    NE=58
    LE=59
    GE=60
    LT=61
    GT=62
    ASSIGN=63
    BANG=64
    QUESTION=65
    AT_SIGN=66
    PLUS=67
    MINUS=68
    STAR=69
    SLASH=70
    PERCENT=71
    LPAREN=72
    RPAREN=73
    LBRACK=74
    RBRACK=75
    HexLiteral=76
    PhysicalLiteral=77
    FloatLiteral=78
    IntLiteral=79
    StringLiteral=80
    Identifier=81
    QuotedIdentifier=82
    NEWLINE=83
    LINE_JOIN=84
    WS=85
    COMMENT=86
    INDENT=87
    DEDENT=88

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
            self.state = 109
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while (((_la) & ~0x3f) == 0 and ((1 << _la) & 24574) != 0) or _la==83:
                self.state = 107
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [1]:
                    self.state = 104
                    self.importStatement()
                    pass
                elif token in [2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 14]:
                    self.state = 105
                    self.declaration()
                    pass
                elif token in [83]:
                    self.state = 106
                    self.match(OpenScenario2Parser.NEWLINE)
                    pass
                else:
                    raise NoViableAltException(self)

                self.state = 111
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 112
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
            self.state = 114
            self.match(OpenScenario2Parser.IMPORT)
            self.state = 117
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [80]:
                self.state = 115
                self.match(OpenScenario2Parser.StringLiteral)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 47, 48, 49, 50, 81, 82]:
                self.state = 116
                self.dottedName()
                pass
            else:
                raise NoViableAltException(self)

            self.state = 119
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
            self.state = 132
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [2, 3]:
                self.enterOuterAlt(localctx, 1)
                self.state = 121
                self.scenarioDeclaration()
                pass
            elif token in [7]:
                self.enterOuterAlt(localctx, 2)
                self.state = 122
                self.physicalTypeDeclaration()
                pass
            elif token in [8]:
                self.enterOuterAlt(localctx, 3)
                self.state = 123
                self.unitDeclaration()
                pass
            elif token in [4]:
                self.enterOuterAlt(localctx, 4)
                self.state = 124
                self.actorDeclaration()
                pass
            elif token in [5]:
                self.enterOuterAlt(localctx, 5)
                self.state = 125
                self.structDeclaration()
                pass
            elif token in [6]:
                self.enterOuterAlt(localctx, 6)
                self.state = 126
                self.enumDeclaration()
                pass
            elif token in [9]:
                self.enterOuterAlt(localctx, 7)
                self.state = 127
                self.globalDeclaration()
                pass
            elif token in [10]:
                self.enterOuterAlt(localctx, 8)
                self.state = 128
                self.extendDeclaration()
                pass
            elif token in [11]:
                self.enterOuterAlt(localctx, 9)
                self.state = 129
                self.modifierDeclaration()
                pass
            elif token in [12]:
                self.enterOuterAlt(localctx, 10)
                self.state = 130
                self.namespaceStatement()
                pass
            elif token in [14]:
                self.enterOuterAlt(localctx, 11)
                self.state = 131
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
            self.state = 134
            localctx.kind = self._input.LT(1)
            _la = self._input.LA(1)
            if not(_la==2 or _la==3):
                localctx.kind = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 135
            self.behaviorName()
            self.state = 137
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 136
                self.inheritance()


            self.state = 150
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [54]:
                self.state = 139
                self.match(OpenScenario2Parser.COLON)
                self.state = 140
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 141
                self.match(OpenScenario2Parser.INDENT)
                self.state = 143 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 142
                    self.scenarioMember()
                    self.state = 145 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112713727410174) != 0) or _la==81 or _la==82):
                        break

                self.state = 147
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [83]:
                self.state = 149
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
            self.state = 155
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,7,self._ctx)
            if la_ == 1:
                self.state = 152
                localctx.actorType = self.identifier()
                self.state = 153
                self.match(OpenScenario2Parser.DOT)


            self.state = 157
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
            self.state = 159
            self.match(OpenScenario2Parser.INHERITS)
            self.state = 160
            localctx.parent = self.behaviorName()
            self.state = 165
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==72:
                self.state = 161
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 162
                localctx.condition = self.expression(0)
                self.state = 163
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
            self.state = 167
            self.match(OpenScenario2Parser.ACTOR)
            self.state = 168
            self.identifier()
            self.state = 170
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 169
                self.inheritance()


            self.state = 183
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [54]:
                self.state = 172
                self.match(OpenScenario2Parser.COLON)
                self.state = 173
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 174
                self.match(OpenScenario2Parser.INDENT)
                self.state = 176 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 175
                    self.structMember()
                    self.state = 178 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112712116797438) != 0) or _la==81 or _la==82):
                        break

                self.state = 180
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [83]:
                self.state = 182
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
            self.state = 185
            self.match(OpenScenario2Parser.STRUCT)
            self.state = 186
            self.identifier()
            self.state = 188
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 187
                self.inheritance()


            self.state = 201
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [54]:
                self.state = 190
                self.match(OpenScenario2Parser.COLON)
                self.state = 191
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 192
                self.match(OpenScenario2Parser.INDENT)
                self.state = 194 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 193
                    self.structMember()
                    self.state = 196 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112712116797438) != 0) or _la==81 or _la==82):
                        break

                self.state = 198
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [83]:
                self.state = 200
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
            self.state = 210
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,15,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 203
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 204
                self.variableDeclaration()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 205
                self.keepConstraint()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 206
                self.removeDefault()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 207
                self.eventDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 208
                self.methodDeclaration()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 209
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
            self.state = 212
            self.match(OpenScenario2Parser.TYPE)
            self.state = 213
            localctx.name = self.identifier()
            self.state = 214
            self.match(OpenScenario2Parser.IS)
            self.state = 215
            localctx.si = self.identifier()
            self.state = 216
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 217
            self.argumentList()
            self.state = 218
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 219
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
            self.state = 221
            self.match(OpenScenario2Parser.UNIT)
            self.state = 222
            localctx.name = self.identifier()
            self.state = 223
            self.match(OpenScenario2Parser.OF)
            self.state = 224
            localctx.type_ = self.identifier()
            self.state = 225
            self.match(OpenScenario2Parser.IS)
            self.state = 226
            localctx.si = self.identifier()
            self.state = 227
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 228
            self.argumentList()
            self.state = 229
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 230
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
            self.state = 232
            self.match(OpenScenario2Parser.ENUM)
            self.state = 233
            self.identifier()
            self.state = 234
            self.match(OpenScenario2Parser.COLON)
            self.state = 235
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 236
            self.enumMember()
            self.state = 241
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,16,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 237
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 238
                    self.enumMember() 
                self.state = 243
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,16,self._ctx)

            self.state = 245
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==53:
                self.state = 244
                self.match(OpenScenario2Parser.COMMA)


            self.state = 247
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 248
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
            self.state = 250
            self.identifier()
            self.state = 253
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==63:
                self.state = 251
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 252
                _la = self._input.LA(1)
                if not(_la==76 or _la==79):
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
            self.state = 255
            self.match(OpenScenario2Parser.GLOBAL)
            self.state = 256
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

        def extensionMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExtensionMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExtensionMemberContext,i)


        def LBRACK(self):
            return self.getToken(OpenScenario2Parser.LBRACK, 0)

        def enumMember(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.EnumMemberContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.EnumMemberContext,i)


        def RBRACK(self):
            return self.getToken(OpenScenario2Parser.RBRACK, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(OpenScenario2Parser.COMMA)
            else:
                return self.getToken(OpenScenario2Parser.COMMA, i)

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
            self.state = 288
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,22,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 258
                self.match(OpenScenario2Parser.EXTEND)
                self.state = 259
                self.behaviorName()
                self.state = 260
                self.match(OpenScenario2Parser.COLON)
                self.state = 261
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 262
                self.match(OpenScenario2Parser.INDENT)
                self.state = 264 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 263
                    self.extensionMember()
                    self.state = 266 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112713727410174) != 0) or _la==81 or _la==82):
                        break

                self.state = 268
                self.match(OpenScenario2Parser.DEDENT)
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 270
                self.match(OpenScenario2Parser.EXTEND)
                self.state = 271
                self.behaviorName()
                self.state = 272
                self.match(OpenScenario2Parser.COLON)
                self.state = 273
                self.match(OpenScenario2Parser.LBRACK)
                self.state = 274
                self.enumMember()
                self.state = 279
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,20,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 275
                        self.match(OpenScenario2Parser.COMMA)
                        self.state = 276
                        self.enumMember() 
                    self.state = 281
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,20,self._ctx)

                self.state = 283
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==53:
                    self.state = 282
                    self.match(OpenScenario2Parser.COMMA)


                self.state = 285
                self.match(OpenScenario2Parser.RBRACK)
                self.state = 286
                self.match(OpenScenario2Parser.NEWLINE)
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExtensionMemberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def scenarioMember(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ScenarioMemberContext,0)


        def enumMember(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EnumMemberContext,0)


        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_extensionMember

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExtensionMember" ):
                return visitor.visitExtensionMember(self)
            else:
                return visitor.visitChildren(self)




    def extensionMember(self):

        localctx = OpenScenario2Parser.ExtensionMemberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 30, self.RULE_extensionMember)
        try:
            self.state = 294
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,23,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 290
                self.scenarioMember()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 291
                self.enumMember()
                self.state = 292
                self.match(OpenScenario2Parser.NEWLINE)
                pass


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
        self.enterRule(localctx, 32, self.RULE_modifierDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 296
            self.match(OpenScenario2Parser.MODIFIER)
            self.state = 297
            self.behaviorName()
            self.state = 300
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==40:
                self.state = 298
                self.match(OpenScenario2Parser.OF)
                self.state = 299
                self.identifier()


            self.state = 313
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [54]:
                self.state = 302
                self.match(OpenScenario2Parser.COLON)
                self.state = 303
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 304
                self.match(OpenScenario2Parser.INDENT)
                self.state = 306 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 305
                    self.scenarioMember()
                    self.state = 308 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112713727410174) != 0) or _la==81 or _la==82):
                        break

                self.state = 310
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [83]:
                self.state = 312
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
        self.enterRule(localctx, 34, self.RULE_namespaceStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 315
            self.match(OpenScenario2Parser.NAMESPACE)
            self.state = 316
            self.identifier()
            self.state = 326
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==13:
                self.state = 317
                self.match(OpenScenario2Parser.USE)
                self.state = 318
                self.identifier()
                self.state = 323
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==53:
                    self.state = 319
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 320
                    self.identifier()
                    self.state = 325
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)



            self.state = 328
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
        self.enterRule(localctx, 36, self.RULE_exportStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 330
            self.match(OpenScenario2Parser.EXPORT)
            self.state = 331
            self.dottedName()
            self.state = 336
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 332
                self.match(OpenScenario2Parser.COMMA)
                self.state = 333
                self.dottedName()
                self.state = 338
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 339
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
        self.enterRule(localctx, 38, self.RULE_scenarioMember)
        try:
            self.state = 351
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,30,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 341
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 342
                self.variableDeclaration()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 343
                self.keepConstraint()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 344
                self.removeDefault()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 345
                self.eventDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 346
                self.methodDeclaration()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 347
                self.coverageDeclaration()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 348
                self.onDirective()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 349
                self.doDirective()
                pass

            elif la_ == 10:
                self.enterOuterAlt(localctx, 10)
                self.state = 350
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
        self.enterRule(localctx, 40, self.RULE_fieldDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 353
            self.identifier()
            self.state = 358
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 354
                self.match(OpenScenario2Parser.COMMA)
                self.state = 355
                self.identifier()
                self.state = 360
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 361
            self.match(OpenScenario2Parser.COLON)
            self.state = 362
            self.typeDeclarator()
            self.state = 365
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==63:
                self.state = 363
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 364
                localctx.defaultValue = self.expression(0)


            self.state = 382
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                self.state = 367
                self.match(OpenScenario2Parser.WITH)
                self.state = 368
                self.match(OpenScenario2Parser.COLON)
                self.state = 379
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [83]:
                    self.state = 369
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 370
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 372 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 371
                        self.fieldConstraint()
                        self.state = 374 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not (_la==17 or _la==20):
                            break

                    self.state = 376
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [17, 20]:
                    self.state = 378
                    self.fieldConstraint()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [83]:
                self.state = 381
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
        self.enterRule(localctx, 42, self.RULE_fieldConstraint)
        try:
            self.state = 386
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [17]:
                self.enterOuterAlt(localctx, 1)
                self.state = 384
                self.keepConstraint()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 385
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
        self.enterRule(localctx, 44, self.RULE_typeDeclarator)
        try:
            self.state = 392
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,37,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 388
                self.match(OpenScenario2Parser.LIST)
                self.state = 389
                self.match(OpenScenario2Parser.OF)
                self.state = 390
                self.identifier()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 391
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

        def sampleExpression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.SampleExpressionContext,0)


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
        self.enterRule(localctx, 46, self.RULE_variableDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 394
            self.match(OpenScenario2Parser.VAR)
            self.state = 395
            self.identifier()
            self.state = 400
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 396
                self.match(OpenScenario2Parser.COMMA)
                self.state = 397
                self.identifier()
                self.state = 402
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 405
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==54:
                self.state = 403
                self.match(OpenScenario2Parser.COLON)
                self.state = 404
                self.typeDeclarator()


            self.state = 412
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==63:
                self.state = 407
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 410
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,40,self._ctx)
                if la_ == 1:
                    self.state = 408
                    self.sampleExpression()
                    pass

                elif la_ == 2:
                    self.state = 409
                    self.expression(0)
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


    class SampleExpressionContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def SAMPLE(self):
            return self.getToken(OpenScenario2Parser.SAMPLE, 0)

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

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

        def eventSpecification(self):
            return self.getTypedRuleContext(OpenScenario2Parser.EventSpecificationContext,0)


        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_sampleExpression

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSampleExpression" ):
                return visitor.visitSampleExpression(self)
            else:
                return visitor.visitChildren(self)




    def sampleExpression(self):

        localctx = OpenScenario2Parser.SampleExpressionContext(self, self._ctx, self.state)
        self.enterRule(localctx, 48, self.RULE_sampleExpression)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 416
            self.match(OpenScenario2Parser.SAMPLE)
            self.state = 417
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 418
            self.expression(0)
            self.state = 419
            self.match(OpenScenario2Parser.COMMA)
            self.state = 420
            self.eventSpecification()
            self.state = 423
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==53:
                self.state = 421
                self.match(OpenScenario2Parser.COMMA)
                self.state = 422
                self.expression(0)


            self.state = 425
            self.match(OpenScenario2Parser.RPAREN)
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
        self.enterRule(localctx, 50, self.RULE_keepConstraint)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 427
            self.match(OpenScenario2Parser.KEEP)
            self.state = 428
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 430
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,43,self._ctx)
            if la_ == 1:
                self.state = 429
                localctx.strength = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==18 or _la==19):
                    localctx.strength = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()


            self.state = 432
            self.expression(0)
            self.state = 433
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 434
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
        self.enterRule(localctx, 52, self.RULE_removeDefault)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 436
            self.match(OpenScenario2Parser.REMOVE_DEFAULT)
            self.state = 437
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 438
            self.expression(0)
            self.state = 439
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 440
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
        self.enterRule(localctx, 54, self.RULE_eventDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 442
            self.match(OpenScenario2Parser.EVENT)
            self.state = 443
            self.identifier()
            self.state = 449
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==72:
                self.state = 444
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 446
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2112711696121854) != 0) or _la==81 or _la==82:
                    self.state = 445
                    self.parameterList()


                self.state = 448
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 453
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==22:
                self.state = 451
                self.match(OpenScenario2Parser.IS)
                self.state = 452
                self.eventSpecification()


            self.state = 455
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
            self.alias = None # IdentifierContext

        def AT_SIGN(self):
            return self.getToken(OpenScenario2Parser.AT_SIGN, 0)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def AS(self):
            return self.getToken(OpenScenario2Parser.AS, 0)

        def IF(self):
            return self.getToken(OpenScenario2Parser.IF, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_eventSpecification

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEventSpecification" ):
                return visitor.visitEventSpecification(self)
            else:
                return visitor.visitChildren(self)




    def eventSpecification(self):

        localctx = OpenScenario2Parser.EventSpecificationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 56, self.RULE_eventSpecification)
        self._la = 0 # Token type
        try:
            self.state = 468
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [66]:
                self.enterOuterAlt(localctx, 1)
                self.state = 457
                self.match(OpenScenario2Parser.AT_SIGN)
                self.state = 458
                self.dottedName()
                self.state = 461
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==47:
                    self.state = 459
                    self.match(OpenScenario2Parser.AS)
                    self.state = 460
                    localctx.alias = self.identifier()


                self.state = 465
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==23:
                    self.state = 463
                    self.match(OpenScenario2Parser.IF)
                    self.state = 464
                    self.expression(0)


                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 44, 45, 46, 47, 48, 49, 50, 67, 68, 72, 74, 76, 77, 78, 79, 80, 81, 82]:
                self.enterOuterAlt(localctx, 2)
                self.state = 467
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

        def EXPRESSION(self):
            return self.getToken(OpenScenario2Parser.EXPRESSION, 0)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)


        def UNDEFINED(self):
            return self.getToken(OpenScenario2Parser.UNDEFINED, 0)

        def EXTERNAL(self):
            return self.getToken(OpenScenario2Parser.EXTERNAL, 0)

        def parameterList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ParameterListContext,0)


        def ARROW(self):
            return self.getToken(OpenScenario2Parser.ARROW, 0)

        def typeDeclarator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeDeclaratorContext,0)


        def ONLY(self):
            return self.getToken(OpenScenario2Parser.ONLY, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_methodDeclaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMethodDeclaration" ):
                return visitor.visitMethodDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def methodDeclaration(self):

        localctx = OpenScenario2Parser.MethodDeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 58, self.RULE_methodDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 470
            self.match(OpenScenario2Parser.DEF)
            self.state = 471
            self.identifier()
            self.state = 472
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 474
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2112711696121854) != 0) or _la==81 or _la==82:
                self.state = 473
                self.parameterList()


            self.state = 476
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 479
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==55:
                self.state = 477
                self.match(OpenScenario2Parser.ARROW)
                self.state = 478
                self.typeDeclarator()


            self.state = 481
            self.match(OpenScenario2Parser.IS)
            self.state = 483
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,52,self._ctx)
            if la_ == 1:
                self.state = 482
                self.match(OpenScenario2Parser.ONLY)


            self.state = 491
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,53,self._ctx)
            if la_ == 1:
                self.state = 485
                self.match(OpenScenario2Parser.EXPRESSION)
                self.state = 486
                self.expression(0)
                pass

            elif la_ == 2:
                self.state = 487
                self.match(OpenScenario2Parser.UNDEFINED)
                pass

            elif la_ == 3:
                self.state = 488
                self.match(OpenScenario2Parser.EXTERNAL)
                self.state = 489
                self.expression(0)
                pass

            elif la_ == 4:
                self.state = 490
                self.expression(0)
                pass


            self.state = 493
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
        self.enterRule(localctx, 60, self.RULE_parameterList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 495
            self.parameter()
            self.state = 500
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 496
                self.match(OpenScenario2Parser.COMMA)
                self.state = 497
                self.parameter()
                self.state = 502
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
        self.enterRule(localctx, 62, self.RULE_parameter)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 503
            self.identifier()
            self.state = 504
            self.match(OpenScenario2Parser.COLON)
            self.state = 505
            self.typeDeclarator()
            self.state = 508
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==63:
                self.state = 506
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 507
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
        self.enterRule(localctx, 64, self.RULE_coverageDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 510
            _la = self._input.LA(1)
            if not(_la==27 or _la==28):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 511
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 513
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                self.state = 512
                self.argumentList()


            self.state = 515
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 516
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
        self.enterRule(localctx, 66, self.RULE_onDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 518
            self.match(OpenScenario2Parser.ON)
            self.state = 519
            self.eventSpecification()
            self.state = 520
            self.match(OpenScenario2Parser.COLON)
            self.state = 521
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 522
            self.match(OpenScenario2Parser.INDENT)
            self.state = 524 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 523
                self.doMember()
                self.state = 526 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2113207764844542) != 0) or _la==81 or _la==82):
                    break

            self.state = 528
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
        self.enterRule(localctx, 68, self.RULE_doDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 530
            self.match(OpenScenario2Parser.DO)
            self.state = 531
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
        self.enterRule(localctx, 70, self.RULE_doMember)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 536
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,58,self._ctx)
            if la_ == 1:
                self.state = 533
                localctx.label = self.identifier()
                self.state = 534
                self.match(OpenScenario2Parser.COLON)


            self.state = 543
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [31, 32, 33]:
                self.state = 538
                self.composition()
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 47, 48, 49, 50, 81, 82]:
                self.state = 539
                self.behaviorInvocation()
                pass
            elif token in [36]:
                self.state = 540
                self.waitDirective()
                pass
            elif token in [37]:
                self.state = 541
                self.emitDirective()
                pass
            elif token in [38]:
                self.state = 542
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
        self.enterRule(localctx, 72, self.RULE_composition)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 545
            self.compositionOperator()
            self.state = 551
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==72:
                self.state = 546
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 548
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                    self.state = 547
                    self.argumentList()


                self.state = 550
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 553
            self.match(OpenScenario2Parser.COLON)
            self.state = 554
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 555
            self.match(OpenScenario2Parser.INDENT)
            self.state = 557 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 556
                self.doMember()
                self.state = 559 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2113207764844542) != 0) or _la==81 or _la==82):
                    break

            self.state = 561
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
        self.enterRule(localctx, 74, self.RULE_compositionOperator)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 563
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
        self.enterRule(localctx, 76, self.RULE_behaviorInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 565
            localctx.target = self.dottedName()
            self.state = 566
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 568
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                self.state = 567
                self.argumentList()


            self.state = 570
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 586
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                self.state = 571
                self.match(OpenScenario2Parser.WITH)
                self.state = 572
                self.match(OpenScenario2Parser.COLON)
                self.state = 583
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [83]:
                    self.state = 573
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 574
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 576 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 575
                        self.behaviorWithMember()
                        self.state = 578 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112746057039870) != 0) or _la==81 or _la==82):
                            break

                    self.state = 580
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 17, 19, 20, 21, 25, 26, 35, 39, 40, 47, 48, 49, 50, 81, 82]:
                    self.state = 582
                    self.behaviorWithMember()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [83]:
                self.state = 585
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
        self.enterRule(localctx, 78, self.RULE_behaviorWithMember)
        try:
            self.state = 592
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 47, 48, 49, 50, 81, 82]:
                self.enterOuterAlt(localctx, 1)
                self.state = 588
                self.modifierInvocation()
                pass
            elif token in [17]:
                self.enterOuterAlt(localctx, 2)
                self.state = 589
                self.keepConstraint()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 3)
                self.state = 590
                self.removeDefault()
                pass
            elif token in [35]:
                self.enterOuterAlt(localctx, 4)
                self.state = 591
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
        self.enterRule(localctx, 80, self.RULE_modifierInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 594
            localctx.target = self.dottedName()
            self.state = 595
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 597
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                self.state = 596
                self.argumentList()


            self.state = 599
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 600
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
        self.enterRule(localctx, 82, self.RULE_untilDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 602
            self.match(OpenScenario2Parser.UNTIL)
            self.state = 603
            self.eventSpecification()
            self.state = 604
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
        self.enterRule(localctx, 84, self.RULE_waitDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 606
            self.match(OpenScenario2Parser.WAIT)
            self.state = 607
            self.eventSpecification()
            self.state = 608
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
        self.enterRule(localctx, 86, self.RULE_emitDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 610
            self.match(OpenScenario2Parser.EMIT)
            self.state = 611
            self.identifier()
            self.state = 617
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==72:
                self.state = 612
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 614
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                    self.state = 613
                    self.argumentList()


                self.state = 616
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 619
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
        self.enterRule(localctx, 88, self.RULE_callDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 621
            self.match(OpenScenario2Parser.CALL)
            self.state = 622
            self.expression(0)
            self.state = 623
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
        self.enterRule(localctx, 90, self.RULE_argumentList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 625
            self.argument()
            self.state = 630
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,71,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 626
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 627
                    self.argument() 
                self.state = 632
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,71,self._ctx)

            self.state = 634
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==53:
                self.state = 633
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
        self.enterRule(localctx, 92, self.RULE_argument)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 639
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,73,self._ctx)
            if la_ == 1:
                self.state = 636
                localctx.name = self.identifier()
                self.state = 637
                self.match(OpenScenario2Parser.COLON)


            self.state = 641
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


    class ElementAccessContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def LBRACK(self):
            return self.getToken(OpenScenario2Parser.LBRACK, 0)
        def RBRACK(self):
            return self.getToken(OpenScenario2Parser.RBRACK, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitElementAccess" ):
                return visitor.visitElementAccess(self)
            else:
                return visitor.visitChildren(self)


    class ConditionalContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expression(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExpressionContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,i)

        def QUESTION(self):
            return self.getToken(OpenScenario2Parser.QUESTION, 0)
        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitConditional" ):
                return visitor.visitConditional(self)
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


    class TypeTestContext(ExpressionContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a OpenScenario2Parser.ExpressionContext
            super().__init__(parser)
            self.op = None # Token
            self.copyFrom(ctx)

        def expression(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ExpressionContext,0)

        def DOT(self):
            return self.getToken(OpenScenario2Parser.DOT, 0)
        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)
        def typeDeclarator(self):
            return self.getTypedRuleContext(OpenScenario2Parser.TypeDeclaratorContext,0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)
        def IS(self):
            return self.getToken(OpenScenario2Parser.IS, 0)
        def AS(self):
            return self.getToken(OpenScenario2Parser.AS, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitTypeTest" ):
                return visitor.visitTypeTest(self)
            else:
                return visitor.visitChildren(self)



    def expression(self, _p:int=0):
        _parentctx = self._ctx
        _parentState = self.state
        localctx = OpenScenario2Parser.ExpressionContext(self, self._ctx, _parentState)
        _prevctx = localctx
        _startState = 94
        self.enterRecursionRule(localctx, 94, self.RULE_expression, _p)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 649
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [67, 68]:
                localctx = OpenScenario2Parser.UnaryContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx

                self.state = 644
                localctx.op = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==67 or _la==68):
                    localctx.op = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                self.state = 645
                self.expression(10)
                pass
            elif token in [44]:
                localctx = OpenScenario2Parser.LogicalNotContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 646
                self.match(OpenScenario2Parser.NOT)
                self.state = 647
                self.expression(6)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 45, 46, 47, 48, 49, 50, 72, 74, 76, 77, 78, 79, 80, 81, 82]:
                localctx = OpenScenario2Parser.PrimaryExpressionContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 648
                self.primary()
                pass
            else:
                raise NoViableAltException(self)

            self._ctx.stop = self._input.LT(-1)
            self.state = 698
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,77,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    if self._parseListeners is not None:
                        self.triggerExitRuleEvent()
                    _prevctx = localctx
                    self.state = 696
                    self._errHandler.sync(self)
                    la_ = self._interp.adaptivePredict(self._input,76,self._ctx)
                    if la_ == 1:
                        localctx = OpenScenario2Parser.MultiplicativeContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 651
                        if not self.precpred(self._ctx, 9):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 9)")
                        self.state = 652
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(((((_la - 69)) & ~0x3f) == 0 and ((1 << (_la - 69)) & 7) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 653
                        self.expression(10)
                        pass

                    elif la_ == 2:
                        localctx = OpenScenario2Parser.AdditiveContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 654
                        if not self.precpred(self._ctx, 8):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 8)")
                        self.state = 655
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(_la==67 or _la==68):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 656
                        self.expression(9)
                        pass

                    elif la_ == 3:
                        localctx = OpenScenario2Parser.RelationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 657
                        if not self.precpred(self._ctx, 7):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 7)")
                        self.state = 658
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 9079259047802175488) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 659
                        self.expression(8)
                        pass

                    elif la_ == 4:
                        localctx = OpenScenario2Parser.LogicalAndContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 660
                        if not self.precpred(self._ctx, 5):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 5)")
                        self.state = 661
                        self.match(OpenScenario2Parser.AND)
                        self.state = 662
                        self.expression(6)
                        pass

                    elif la_ == 5:
                        localctx = OpenScenario2Parser.LogicalOrContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 663
                        if not self.precpred(self._ctx, 4):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 4)")
                        self.state = 664
                        self.match(OpenScenario2Parser.OR)
                        self.state = 665
                        self.expression(5)
                        pass

                    elif la_ == 6:
                        localctx = OpenScenario2Parser.ImplicationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 666
                        if not self.precpred(self._ctx, 3):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 3)")
                        self.state = 667
                        self.match(OpenScenario2Parser.IMPLIES)
                        self.state = 668
                        self.expression(3)
                        pass

                    elif la_ == 7:
                        localctx = OpenScenario2Parser.ConditionalContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 669
                        if not self.precpred(self._ctx, 2):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 2)")
                        self.state = 670
                        self.match(OpenScenario2Parser.QUESTION)
                        self.state = 671
                        self.expression(0)
                        self.state = 672
                        self.match(OpenScenario2Parser.COLON)
                        self.state = 673
                        self.expression(2)
                        pass

                    elif la_ == 8:
                        localctx = OpenScenario2Parser.TypeTestContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 675
                        if not self.precpred(self._ctx, 14):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 14)")
                        self.state = 676
                        self.match(OpenScenario2Parser.DOT)
                        self.state = 677
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(_la==22 or _la==47):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 678
                        self.match(OpenScenario2Parser.LPAREN)
                        self.state = 679
                        self.typeDeclarator()
                        self.state = 680
                        self.match(OpenScenario2Parser.RPAREN)
                        pass

                    elif la_ == 9:
                        localctx = OpenScenario2Parser.MemberAccessContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 682
                        if not self.precpred(self._ctx, 13):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 13)")
                        self.state = 683
                        self.match(OpenScenario2Parser.DOT)
                        self.state = 684
                        self.identifier()
                        pass

                    elif la_ == 10:
                        localctx = OpenScenario2Parser.ElementAccessContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 685
                        if not self.precpred(self._ctx, 12):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 12)")
                        self.state = 686
                        self.match(OpenScenario2Parser.LBRACK)
                        self.state = 687
                        self.expression(0)
                        self.state = 688
                        self.match(OpenScenario2Parser.RBRACK)
                        pass

                    elif la_ == 11:
                        localctx = OpenScenario2Parser.CallContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 690
                        if not self.precpred(self._ctx, 11):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 11)")
                        self.state = 691
                        self.match(OpenScenario2Parser.LPAREN)
                        self.state = 693
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                            self.state = 692
                            self.argumentList()


                        self.state = 695
                        self.match(OpenScenario2Parser.RPAREN)
                        pass

             
                self.state = 700
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,77,self._ctx)

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
        self.enterRule(localctx, 96, self.RULE_primary)
        self._la = 0 # Token type
        try:
            self.state = 730
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,81,self._ctx)
            if la_ == 1:
                localctx = OpenScenario2Parser.PhysicalLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 701
                self.match(OpenScenario2Parser.PhysicalLiteral)
                pass

            elif la_ == 2:
                localctx = OpenScenario2Parser.NumberLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 702
                _la = self._input.LA(1)
                if not(((((_la - 76)) & ~0x3f) == 0 and ((1 << (_la - 76)) & 13) != 0)):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 3:
                localctx = OpenScenario2Parser.StringLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 703
                self.match(OpenScenario2Parser.StringLiteral)
                pass

            elif la_ == 4:
                localctx = OpenScenario2Parser.BoolLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 704
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
                self.state = 705
                self.rangeLiteral()
                pass

            elif la_ == 6:
                localctx = OpenScenario2Parser.ListLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 706
                self.match(OpenScenario2Parser.LBRACK)
                self.state = 718
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2235856998432766) != 0) or ((((_la - 67)) & ~0x3f) == 0 and ((1 << (_la - 67)) & 65187) != 0):
                    self.state = 707
                    self.expression(0)
                    self.state = 712
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,78,self._ctx)
                    while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                        if _alt==1:
                            self.state = 708
                            self.match(OpenScenario2Parser.COMMA)
                            self.state = 709
                            self.expression(0) 
                        self.state = 714
                        self._errHandler.sync(self)
                        _alt = self._interp.adaptivePredict(self._input,78,self._ctx)

                    self.state = 716
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if _la==53:
                        self.state = 715
                        self.match(OpenScenario2Parser.COMMA)




                self.state = 720
                self.match(OpenScenario2Parser.RBRACK)
                pass

            elif la_ == 7:
                localctx = OpenScenario2Parser.EnumValueContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 721
                localctx.enumType = self.identifier()
                self.state = 722
                self.match(OpenScenario2Parser.BANG)
                self.state = 723
                localctx.member = self.identifier()
                pass

            elif la_ == 8:
                localctx = OpenScenario2Parser.NamePrimaryContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 725
                self.identifier()
                pass

            elif la_ == 9:
                localctx = OpenScenario2Parser.ParenthesisedContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 726
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 727
                self.expression(0)
                self.state = 728
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
        self.enterRule(localctx, 98, self.RULE_rangeLiteral)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 732
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 733
            localctx.low = self.expression(0)
            self.state = 734
            self.match(OpenScenario2Parser.DOUBLEDOT)
            self.state = 735
            localctx.high = self.expression(0)
            self.state = 736
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 738
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,82,self._ctx)
            if la_ == 1:
                self.state = 737
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
        self.enterRule(localctx, 100, self.RULE_dottedName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 740
            self.identifier()
            self.state = 745
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==52:
                self.state = 741
                self.match(OpenScenario2Parser.DOT)
                self.state = 742
                self.identifier()
                self.state = 747
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

        def NAMESPACE(self):
            return self.getToken(OpenScenario2Parser.NAMESPACE, 0)

        def USE(self):
            return self.getToken(OpenScenario2Parser.USE, 0)

        def EXPORT(self):
            return self.getToken(OpenScenario2Parser.EXPORT, 0)

        def GLOBAL(self):
            return self.getToken(OpenScenario2Parser.GLOBAL, 0)

        def INHERITS(self):
            return self.getToken(OpenScenario2Parser.INHERITS, 0)

        def IMPORT(self):
            return self.getToken(OpenScenario2Parser.IMPORT, 0)

        def AS(self):
            return self.getToken(OpenScenario2Parser.AS, 0)

        def ONLY(self):
            return self.getToken(OpenScenario2Parser.ONLY, 0)

        def EXPRESSION(self):
            return self.getToken(OpenScenario2Parser.EXPRESSION, 0)

        def SAMPLE(self):
            return self.getToken(OpenScenario2Parser.SAMPLE, 0)

        def ENUM(self):
            return self.getToken(OpenScenario2Parser.ENUM, 0)

        def STRUCT(self):
            return self.getToken(OpenScenario2Parser.STRUCT, 0)

        def ACTOR(self):
            return self.getToken(OpenScenario2Parser.ACTOR, 0)

        def SCENARIO(self):
            return self.getToken(OpenScenario2Parser.SCENARIO, 0)

        def EXTEND(self):
            return self.getToken(OpenScenario2Parser.EXTEND, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_identifier

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIdentifier" ):
                return visitor.visitIdentifier(self)
            else:
                return visitor.visitChildren(self)




    def identifier(self):

        localctx = OpenScenario2Parser.IdentifierContext(self, self._ctx, self.state)
        self.enterRule(localctx, 102, self.RULE_identifier)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 748
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112711696121854) != 0) or _la==81 or _la==82):
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
        self._predicates[47] = self.expression_sempred
        pred = self._predicates.get(ruleIndex, None)
        if pred is None:
            raise Exception("No predicate with index:" + str(ruleIndex))
        else:
            return pred(localctx, predIndex)

    def expression_sempred(self, localctx:ExpressionContext, predIndex:int):
            if predIndex == 0:
                return self.precpred(self._ctx, 9)
         

            if predIndex == 1:
                return self.precpred(self._ctx, 8)
         

            if predIndex == 2:
                return self.precpred(self._ctx, 7)
         

            if predIndex == 3:
                return self.precpred(self._ctx, 5)
         

            if predIndex == 4:
                return self.precpred(self._ctx, 4)
         

            if predIndex == 5:
                return self.precpred(self._ctx, 3)
         

            if predIndex == 6:
                return self.precpred(self._ctx, 2)
         

            if predIndex == 7:
                return self.precpred(self._ctx, 14)
         

            if predIndex == 8:
                return self.precpred(self._ctx, 13)
         

            if predIndex == 9:
                return self.precpred(self._ctx, 12)
         

            if predIndex == 10:
                return self.precpred(self._ctx, 11)
         




