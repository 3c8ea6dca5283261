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
        4,1,89,779,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,2,43,7,43,2,44,7,44,2,45,7,45,2,46,
        7,46,2,47,7,47,2,48,7,48,2,49,7,49,2,50,7,50,2,51,7,51,2,52,7,52,
        2,53,7,53,1,0,1,0,1,0,5,0,112,8,0,10,0,12,0,115,9,0,1,0,1,0,1,1,
        1,1,1,1,3,1,122,8,1,1,1,1,1,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,1,2,
        1,2,1,2,3,2,137,8,2,1,3,1,3,1,3,3,3,142,8,3,1,3,1,3,1,3,1,3,4,3,
        148,8,3,11,3,12,3,149,1,3,1,3,1,3,3,3,155,8,3,1,4,1,4,1,4,3,4,160,
        8,4,1,4,1,4,1,5,1,5,1,5,1,5,1,5,1,5,3,5,170,8,5,1,6,1,6,1,6,3,6,
        175,8,6,1,6,1,6,1,6,1,6,4,6,181,8,6,11,6,12,6,182,1,6,1,6,1,6,3,
        6,188,8,6,1,7,1,7,1,7,3,7,193,8,7,1,7,1,7,1,7,1,7,4,7,199,8,7,11,
        7,12,7,200,1,7,1,7,1,7,3,7,206,8,7,1,8,1,8,1,8,1,8,1,8,1,8,1,8,3,
        8,215,8,8,1,9,1,9,1,9,1,9,1,9,1,9,1,9,1,9,1,9,1,10,1,10,1,10,1,10,
        1,10,1,10,1,10,1,10,1,10,1,10,1,10,1,11,1,11,1,11,1,11,1,11,1,11,
        1,11,5,11,244,8,11,10,11,12,11,247,9,11,1,11,3,11,250,8,11,1,11,
        1,11,1,11,1,12,1,12,1,12,3,12,258,8,12,1,13,1,13,1,13,1,14,1,14,
        1,14,1,14,1,14,1,14,4,14,269,8,14,11,14,12,14,270,1,14,1,14,1,14,
        1,14,1,14,1,14,1,14,1,14,1,14,5,14,282,8,14,10,14,12,14,285,9,14,
        1,14,3,14,288,8,14,1,14,1,14,1,14,3,14,293,8,14,1,15,1,15,1,15,1,
        15,3,15,299,8,15,1,16,1,16,1,16,1,16,3,16,305,8,16,1,16,1,16,1,16,
        1,16,4,16,311,8,16,11,16,12,16,312,1,16,1,16,1,16,3,16,318,8,16,
        1,17,1,17,1,17,1,17,1,17,1,17,5,17,326,8,17,10,17,12,17,329,9,17,
        3,17,331,8,17,1,17,1,17,1,18,1,18,1,18,1,18,5,18,339,8,18,10,18,
        12,18,342,9,18,1,18,1,18,1,19,1,19,3,19,348,8,19,1,19,3,19,351,8,
        19,1,19,3,19,354,8,19,1,20,1,20,1,20,1,20,1,20,1,20,1,20,1,20,1,
        20,1,20,3,20,366,8,20,1,21,1,21,1,21,5,21,371,8,21,10,21,12,21,374,
        9,21,1,21,1,21,1,21,1,21,3,21,380,8,21,1,21,1,21,1,21,1,21,1,21,
        4,21,387,8,21,11,21,12,21,388,1,21,1,21,1,21,3,21,394,8,21,1,21,
        3,21,397,8,21,1,22,1,22,1,22,3,22,402,8,22,1,23,1,23,1,23,1,23,3,
        23,408,8,23,1,24,1,24,1,24,1,24,5,24,414,8,24,10,24,12,24,417,9,
        24,1,24,1,24,3,24,421,8,24,1,24,1,24,1,24,3,24,426,8,24,3,24,428,
        8,24,1,24,1,24,1,25,1,25,1,25,1,25,1,25,1,25,1,25,3,25,439,8,25,
        1,25,1,25,1,26,1,26,1,26,3,26,446,8,26,1,26,1,26,1,26,1,26,1,27,
        1,27,1,27,1,27,1,27,1,27,1,28,1,28,1,28,1,28,3,28,462,8,28,1,28,
        3,28,465,8,28,1,28,1,28,3,28,469,8,28,1,28,1,28,1,29,1,29,1,29,1,
        29,3,29,477,8,29,1,29,1,29,3,29,481,8,29,1,29,3,29,484,8,29,1,30,
        1,30,1,30,1,30,3,30,490,8,30,1,30,1,30,1,30,3,30,495,8,30,1,30,1,
        30,3,30,499,8,30,1,30,1,30,1,30,1,30,1,30,1,30,3,30,507,8,30,1,30,
        1,30,1,31,1,31,1,31,5,31,514,8,31,10,31,12,31,517,9,31,1,32,1,32,
        1,32,1,32,1,32,3,32,524,8,32,1,33,1,33,1,33,3,33,529,8,33,1,33,1,
        33,1,33,1,34,1,34,1,34,1,34,1,34,1,34,4,34,540,8,34,11,34,12,34,
        541,1,34,1,34,1,35,1,35,1,35,1,36,1,36,1,36,3,36,552,8,36,1,36,1,
        36,1,36,1,36,1,36,3,36,559,8,36,1,37,1,37,1,37,3,37,564,8,37,1,37,
        3,37,567,8,37,1,37,1,37,1,37,1,37,4,37,573,8,37,11,37,12,37,574,
        1,37,1,37,1,38,1,38,1,39,1,39,1,39,3,39,584,8,39,1,39,1,39,1,39,
        1,39,1,39,1,39,4,39,592,8,39,11,39,12,39,593,1,39,1,39,1,39,3,39,
        599,8,39,1,39,3,39,602,8,39,1,40,1,40,1,40,1,40,3,40,608,8,40,1,
        41,1,41,1,41,3,41,613,8,41,1,41,1,41,1,41,3,41,618,8,41,1,41,1,41,
        1,41,1,42,1,42,1,42,1,42,1,43,1,43,1,43,1,43,1,44,1,44,1,44,1,44,
        3,44,635,8,44,1,44,3,44,638,8,44,1,44,1,44,1,45,1,45,1,45,1,45,1,
        46,1,46,1,46,5,46,649,8,46,10,46,12,46,652,9,46,1,46,3,46,655,8,
        46,1,47,1,47,1,47,3,47,660,8,47,1,47,1,47,1,48,1,48,1,48,1,48,1,
        48,1,48,3,48,670,8,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,
        48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,
        48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,1,
        48,1,48,1,48,1,48,1,48,1,48,1,48,1,48,3,48,714,8,48,1,48,5,48,717,
        8,48,10,48,12,48,720,9,48,1,49,1,49,1,49,1,49,1,49,1,49,1,49,1,49,
        1,49,5,49,731,8,49,10,49,12,49,734,9,49,1,49,3,49,737,8,49,3,49,
        739,8,49,1,49,1,49,1,49,1,49,1,49,1,49,1,49,1,49,1,49,1,49,3,49,
        751,8,49,1,50,1,50,1,50,1,50,1,50,1,50,3,50,759,8,50,1,51,1,51,1,
        51,5,51,764,8,51,10,51,12,51,767,9,51,1,52,3,52,770,8,52,1,52,3,
        52,773,8,52,1,52,1,52,1,53,1,53,1,53,0,1,96,54,0,2,4,6,8,10,12,14,
        16,18,20,22,24,26,28,30,32,34,36,38,40,42,44,46,48,50,52,54,56,58,
        60,62,64,66,68,70,72,74,76,78,80,82,84,86,88,90,92,94,96,98,100,
        102,104,106,0,12,1,0,2,3,2,0,77,77,80,80,1,0,18,19,1,0,27,28,1,0,
        31,33,1,0,68,69,1,0,70,72,2,0,41,41,58,63,2,0,22,22,47,47,2,0,77,
        77,79,80,1,0,45,46,7,0,1,15,19,19,21,21,25,26,39,40,47,50,82,83,
        862,0,113,1,0,0,0,2,118,1,0,0,0,4,136,1,0,0,0,6,138,1,0,0,0,8,159,
        1,0,0,0,10,163,1,0,0,0,12,171,1,0,0,0,14,189,1,0,0,0,16,214,1,0,
        0,0,18,216,1,0,0,0,20,225,1,0,0,0,22,236,1,0,0,0,24,254,1,0,0,0,
        26,259,1,0,0,0,28,292,1,0,0,0,30,298,1,0,0,0,32,300,1,0,0,0,34,319,
        1,0,0,0,36,334,1,0,0,0,38,353,1,0,0,0,40,365,1,0,0,0,42,367,1,0,
        0,0,44,401,1,0,0,0,46,407,1,0,0,0,48,409,1,0,0,0,50,431,1,0,0,0,
        52,442,1,0,0,0,54,451,1,0,0,0,56,457,1,0,0,0,58,483,1,0,0,0,60,485,
        1,0,0,0,62,510,1,0,0,0,64,518,1,0,0,0,66,525,1,0,0,0,68,533,1,0,
        0,0,70,545,1,0,0,0,72,551,1,0,0,0,74,560,1,0,0,0,76,578,1,0,0,0,
        78,580,1,0,0,0,80,607,1,0,0,0,82,612,1,0,0,0,84,622,1,0,0,0,86,626,
        1,0,0,0,88,630,1,0,0,0,90,641,1,0,0,0,92,645,1,0,0,0,94,659,1,0,
        0,0,96,669,1,0,0,0,98,750,1,0,0,0,100,752,1,0,0,0,102,760,1,0,0,
        0,104,772,1,0,0,0,106,776,1,0,0,0,108,112,3,2,1,0,109,112,3,4,2,
        0,110,112,5,84,0,0,111,108,1,0,0,0,111,109,1,0,0,0,111,110,1,0,0,
        0,112,115,1,0,0,0,113,111,1,0,0,0,113,114,1,0,0,0,114,116,1,0,0,
        0,115,113,1,0,0,0,116,117,5,0,0,1,117,1,1,0,0,0,118,121,5,1,0,0,
        119,122,5,81,0,0,120,122,3,102,51,0,121,119,1,0,0,0,121,120,1,0,
        0,0,122,123,1,0,0,0,123,124,5,84,0,0,124,3,1,0,0,0,125,137,3,6,3,
        0,126,137,3,18,9,0,127,137,3,20,10,0,128,137,3,12,6,0,129,137,3,
        14,7,0,130,137,3,22,11,0,131,137,3,26,13,0,132,137,3,28,14,0,133,
        137,3,32,16,0,134,137,3,34,17,0,135,137,3,36,18,0,136,125,1,0,0,
        0,136,126,1,0,0,0,136,127,1,0,0,0,136,128,1,0,0,0,136,129,1,0,0,
        0,136,130,1,0,0,0,136,131,1,0,0,0,136,132,1,0,0,0,136,133,1,0,0,
        0,136,134,1,0,0,0,136,135,1,0,0,0,137,5,1,0,0,0,138,139,7,0,0,0,
        139,141,3,8,4,0,140,142,3,10,5,0,141,140,1,0,0,0,141,142,1,0,0,0,
        142,154,1,0,0,0,143,144,5,55,0,0,144,145,5,84,0,0,145,147,5,88,0,
        0,146,148,3,40,20,0,147,146,1,0,0,0,148,149,1,0,0,0,149,147,1,0,
        0,0,149,150,1,0,0,0,150,151,1,0,0,0,151,152,5,89,0,0,152,155,1,0,
        0,0,153,155,5,84,0,0,154,143,1,0,0,0,154,153,1,0,0,0,155,7,1,0,0,
        0,156,157,3,104,52,0,157,158,5,52,0,0,158,160,1,0,0,0,159,156,1,
        0,0,0,159,160,1,0,0,0,160,161,1,0,0,0,161,162,3,104,52,0,162,9,1,
        0,0,0,163,164,5,15,0,0,164,169,3,8,4,0,165,166,5,73,0,0,166,167,
        3,96,48,0,167,168,5,74,0,0,168,170,1,0,0,0,169,165,1,0,0,0,169,170,
        1,0,0,0,170,11,1,0,0,0,171,172,5,4,0,0,172,174,3,104,52,0,173,175,
        3,10,5,0,174,173,1,0,0,0,174,175,1,0,0,0,175,187,1,0,0,0,176,177,
        5,55,0,0,177,178,5,84,0,0,178,180,5,88,0,0,179,181,3,16,8,0,180,
        179,1,0,0,0,181,182,1,0,0,0,182,180,1,0,0,0,182,183,1,0,0,0,183,
        184,1,0,0,0,184,185,5,89,0,0,185,188,1,0,0,0,186,188,5,84,0,0,187,
        176,1,0,0,0,187,186,1,0,0,0,188,13,1,0,0,0,189,190,5,5,0,0,190,192,
        3,104,52,0,191,193,3,10,5,0,192,191,1,0,0,0,192,193,1,0,0,0,193,
        205,1,0,0,0,194,195,5,55,0,0,195,196,5,84,0,0,196,198,5,88,0,0,197,
        199,3,16,8,0,198,197,1,0,0,0,199,200,1,0,0,0,200,198,1,0,0,0,200,
        201,1,0,0,0,201,202,1,0,0,0,202,203,5,89,0,0,203,206,1,0,0,0,204,
        206,5,84,0,0,205,194,1,0,0,0,205,204,1,0,0,0,206,15,1,0,0,0,207,
        215,3,42,21,0,208,215,3,48,24,0,209,215,3,52,26,0,210,215,3,54,27,
        0,211,215,3,56,28,0,212,215,3,60,30,0,213,215,3,66,33,0,214,207,
        1,0,0,0,214,208,1,0,0,0,214,209,1,0,0,0,214,210,1,0,0,0,214,211,
        1,0,0,0,214,212,1,0,0,0,214,213,1,0,0,0,215,17,1,0,0,0,216,217,5,
        7,0,0,217,218,3,104,52,0,218,219,5,22,0,0,219,220,3,104,52,0,220,
        221,5,73,0,0,221,222,3,92,46,0,222,223,5,74,0,0,223,224,5,84,0,0,
        224,19,1,0,0,0,225,226,5,8,0,0,226,227,3,104,52,0,227,228,5,40,0,
        0,228,229,3,104,52,0,229,230,5,22,0,0,230,231,3,104,52,0,231,232,
        5,73,0,0,232,233,3,92,46,0,233,234,5,74,0,0,234,235,5,84,0,0,235,
        21,1,0,0,0,236,237,5,6,0,0,237,238,3,104,52,0,238,239,5,55,0,0,239,
        240,5,75,0,0,240,245,3,24,12,0,241,242,5,53,0,0,242,244,3,24,12,
        0,243,241,1,0,0,0,244,247,1,0,0,0,245,243,1,0,0,0,245,246,1,0,0,
        0,246,249,1,0,0,0,247,245,1,0,0,0,248,250,5,53,0,0,249,248,1,0,0,
        0,249,250,1,0,0,0,250,251,1,0,0,0,251,252,5,76,0,0,252,253,5,84,
        0,0,253,23,1,0,0,0,254,257,3,104,52,0,255,256,5,64,0,0,256,258,7,
        1,0,0,257,255,1,0,0,0,257,258,1,0,0,0,258,25,1,0,0,0,259,260,5,9,
        0,0,260,261,3,42,21,0,261,27,1,0,0,0,262,263,5,10,0,0,263,264,3,
        8,4,0,264,265,5,55,0,0,265,266,5,84,0,0,266,268,5,88,0,0,267,269,
        3,30,15,0,268,267,1,0,0,0,269,270,1,0,0,0,270,268,1,0,0,0,270,271,
        1,0,0,0,271,272,1,0,0,0,272,273,5,89,0,0,273,293,1,0,0,0,274,275,
        5,10,0,0,275,276,3,8,4,0,276,277,5,55,0,0,277,278,5,75,0,0,278,283,
        3,24,12,0,279,280,5,53,0,0,280,282,3,24,12,0,281,279,1,0,0,0,282,
        285,1,0,0,0,283,281,1,0,0,0,283,284,1,0,0,0,284,287,1,0,0,0,285,
        283,1,0,0,0,286,288,5,53,0,0,287,286,1,0,0,0,287,288,1,0,0,0,288,
        289,1,0,0,0,289,290,5,76,0,0,290,291,5,84,0,0,291,293,1,0,0,0,292,
        262,1,0,0,0,292,274,1,0,0,0,293,29,1,0,0,0,294,299,3,40,20,0,295,
        296,3,24,12,0,296,297,5,84,0,0,297,299,1,0,0,0,298,294,1,0,0,0,298,
        295,1,0,0,0,299,31,1,0,0,0,300,301,5,11,0,0,301,304,3,8,4,0,302,
        303,5,40,0,0,303,305,3,104,52,0,304,302,1,0,0,0,304,305,1,0,0,0,
        305,317,1,0,0,0,306,307,5,55,0,0,307,308,5,84,0,0,308,310,5,88,0,
        0,309,311,3,40,20,0,310,309,1,0,0,0,311,312,1,0,0,0,312,310,1,0,
        0,0,312,313,1,0,0,0,313,314,1,0,0,0,314,315,5,89,0,0,315,318,1,0,
        0,0,316,318,5,84,0,0,317,306,1,0,0,0,317,316,1,0,0,0,318,33,1,0,
        0,0,319,320,5,12,0,0,320,330,3,104,52,0,321,322,5,13,0,0,322,327,
        3,104,52,0,323,324,5,53,0,0,324,326,3,104,52,0,325,323,1,0,0,0,326,
        329,1,0,0,0,327,325,1,0,0,0,327,328,1,0,0,0,328,331,1,0,0,0,329,
        327,1,0,0,0,330,321,1,0,0,0,330,331,1,0,0,0,331,332,1,0,0,0,332,
        333,5,84,0,0,333,35,1,0,0,0,334,335,5,14,0,0,335,340,3,38,19,0,336,
        337,5,53,0,0,337,339,3,38,19,0,338,336,1,0,0,0,339,342,1,0,0,0,340,
        338,1,0,0,0,340,341,1,0,0,0,341,343,1,0,0,0,342,340,1,0,0,0,343,
        344,5,84,0,0,344,37,1,0,0,0,345,354,3,102,51,0,346,348,3,106,53,
        0,347,346,1,0,0,0,347,348,1,0,0,0,348,349,1,0,0,0,349,351,5,54,0,
        0,350,347,1,0,0,0,350,351,1,0,0,0,351,352,1,0,0,0,352,354,5,70,0,
        0,353,345,1,0,0,0,353,350,1,0,0,0,354,39,1,0,0,0,355,366,3,42,21,
        0,356,366,3,48,24,0,357,366,3,52,26,0,358,366,3,54,27,0,359,366,
        3,56,28,0,360,366,3,60,30,0,361,366,3,66,33,0,362,366,3,68,34,0,
        363,366,3,70,35,0,364,366,3,82,41,0,365,355,1,0,0,0,365,356,1,0,
        0,0,365,357,1,0,0,0,365,358,1,0,0,0,365,359,1,0,0,0,365,360,1,0,
        0,0,365,361,1,0,0,0,365,362,1,0,0,0,365,363,1,0,0,0,365,364,1,0,
        0,0,366,41,1,0,0,0,367,372,3,104,52,0,368,369,5,53,0,0,369,371,3,
        104,52,0,370,368,1,0,0,0,371,374,1,0,0,0,372,370,1,0,0,0,372,373,
        1,0,0,0,373,375,1,0,0,0,374,372,1,0,0,0,375,376,5,55,0,0,376,379,
        3,46,23,0,377,378,5,64,0,0,378,380,3,96,48,0,379,377,1,0,0,0,379,
        380,1,0,0,0,380,396,1,0,0,0,381,382,5,34,0,0,382,393,5,55,0,0,383,
        384,5,84,0,0,384,386,5,88,0,0,385,387,3,44,22,0,386,385,1,0,0,0,
        387,388,1,0,0,0,388,386,1,0,0,0,388,389,1,0,0,0,389,390,1,0,0,0,
        390,391,5,89,0,0,391,394,1,0,0,0,392,394,3,44,22,0,393,383,1,0,0,
        0,393,392,1,0,0,0,394,397,1,0,0,0,395,397,5,84,0,0,396,381,1,0,0,
        0,396,395,1,0,0,0,397,43,1,0,0,0,398,402,3,52,26,0,399,402,3,54,
        27,0,400,402,3,66,33,0,401,398,1,0,0,0,401,399,1,0,0,0,401,400,1,
        0,0,0,402,45,1,0,0,0,403,404,5,39,0,0,404,405,5,40,0,0,405,408,3,
        104,52,0,406,408,3,104,52,0,407,403,1,0,0,0,407,406,1,0,0,0,408,
        47,1,0,0,0,409,410,5,16,0,0,410,415,3,104,52,0,411,412,5,53,0,0,
        412,414,3,104,52,0,413,411,1,0,0,0,414,417,1,0,0,0,415,413,1,0,0,
        0,415,416,1,0,0,0,416,420,1,0,0,0,417,415,1,0,0,0,418,419,5,55,0,
        0,419,421,3,46,23,0,420,418,1,0,0,0,420,421,1,0,0,0,421,427,1,0,
        0,0,422,425,5,64,0,0,423,426,3,50,25,0,424,426,3,96,48,0,425,423,
        1,0,0,0,425,424,1,0,0,0,426,428,1,0,0,0,427,422,1,0,0,0,427,428,
        1,0,0,0,428,429,1,0,0,0,429,430,5,84,0,0,430,49,1,0,0,0,431,432,
        5,50,0,0,432,433,5,73,0,0,433,434,3,96,48,0,434,435,5,53,0,0,435,
        438,3,58,29,0,436,437,5,53,0,0,437,439,3,96,48,0,438,436,1,0,0,0,
        438,439,1,0,0,0,439,440,1,0,0,0,440,441,5,74,0,0,441,51,1,0,0,0,
        442,443,5,17,0,0,443,445,5,73,0,0,444,446,7,2,0,0,445,444,1,0,0,
        0,445,446,1,0,0,0,446,447,1,0,0,0,447,448,3,96,48,0,448,449,5,74,
        0,0,449,450,5,84,0,0,450,53,1,0,0,0,451,452,5,20,0,0,452,453,5,73,
        0,0,453,454,3,96,48,0,454,455,5,74,0,0,455,456,5,84,0,0,456,55,1,
        0,0,0,457,458,5,21,0,0,458,464,3,104,52,0,459,461,5,73,0,0,460,462,
        3,62,31,0,461,460,1,0,0,0,461,462,1,0,0,0,462,463,1,0,0,0,463,465,
        5,74,0,0,464,459,1,0,0,0,464,465,1,0,0,0,465,468,1,0,0,0,466,467,
        5,22,0,0,467,469,3,58,29,0,468,466,1,0,0,0,468,469,1,0,0,0,469,470,
        1,0,0,0,470,471,5,84,0,0,471,57,1,0,0,0,472,473,5,67,0,0,473,476,
        3,102,51,0,474,475,5,47,0,0,475,477,3,104,52,0,476,474,1,0,0,0,476,
        477,1,0,0,0,477,480,1,0,0,0,478,479,5,23,0,0,479,481,3,96,48,0,480,
        478,1,0,0,0,480,481,1,0,0,0,481,484,1,0,0,0,482,484,3,96,48,0,483,
        472,1,0,0,0,483,482,1,0,0,0,484,59,1,0,0,0,485,486,5,24,0,0,486,
        487,3,104,52,0,487,489,5,73,0,0,488,490,3,62,31,0,489,488,1,0,0,
        0,489,490,1,0,0,0,490,491,1,0,0,0,491,494,5,74,0,0,492,493,5,56,
        0,0,493,495,3,46,23,0,494,492,1,0,0,0,494,495,1,0,0,0,495,496,1,
        0,0,0,496,498,5,22,0,0,497,499,5,48,0,0,498,497,1,0,0,0,498,499,
        1,0,0,0,499,506,1,0,0,0,500,501,5,49,0,0,501,507,3,96,48,0,502,507,
        5,26,0,0,503,504,5,25,0,0,504,507,3,96,48,0,505,507,3,96,48,0,506,
        500,1,0,0,0,506,502,1,0,0,0,506,503,1,0,0,0,506,505,1,0,0,0,507,
        508,1,0,0,0,508,509,5,84,0,0,509,61,1,0,0,0,510,515,3,64,32,0,511,
        512,5,53,0,0,512,514,3,64,32,0,513,511,1,0,0,0,514,517,1,0,0,0,515,
        513,1,0,0,0,515,516,1,0,0,0,516,63,1,0,0,0,517,515,1,0,0,0,518,519,
        3,104,52,0,519,520,5,55,0,0,520,523,3,46,23,0,521,522,5,64,0,0,522,
        524,3,96,48,0,523,521,1,0,0,0,523,524,1,0,0,0,524,65,1,0,0,0,525,
        526,7,3,0,0,526,528,5,73,0,0,527,529,3,92,46,0,528,527,1,0,0,0,528,
        529,1,0,0,0,529,530,1,0,0,0,530,531,5,74,0,0,531,532,5,84,0,0,532,
        67,1,0,0,0,533,534,5,29,0,0,534,535,3,58,29,0,535,536,5,55,0,0,536,
        537,5,84,0,0,537,539,5,88,0,0,538,540,3,72,36,0,539,538,1,0,0,0,
        540,541,1,0,0,0,541,539,1,0,0,0,541,542,1,0,0,0,542,543,1,0,0,0,
        543,544,5,89,0,0,544,69,1,0,0,0,545,546,5,30,0,0,546,547,3,72,36,
        0,547,71,1,0,0,0,548,549,3,104,52,0,549,550,5,55,0,0,550,552,1,0,
        0,0,551,548,1,0,0,0,551,552,1,0,0,0,552,558,1,0,0,0,553,559,3,74,
        37,0,554,559,3,78,39,0,555,559,3,86,43,0,556,559,3,88,44,0,557,559,
        3,90,45,0,558,553,1,0,0,0,558,554,1,0,0,0,558,555,1,0,0,0,558,556,
        1,0,0,0,558,557,1,0,0,0,559,73,1,0,0,0,560,566,3,76,38,0,561,563,
        5,73,0,0,562,564,3,92,46,0,563,562,1,0,0,0,563,564,1,0,0,0,564,565,
        1,0,0,0,565,567,5,74,0,0,566,561,1,0,0,0,566,567,1,0,0,0,567,568,
        1,0,0,0,568,569,5,55,0,0,569,570,5,84,0,0,570,572,5,88,0,0,571,573,
        3,72,36,0,572,571,1,0,0,0,573,574,1,0,0,0,574,572,1,0,0,0,574,575,
        1,0,0,0,575,576,1,0,0,0,576,577,5,89,0,0,577,75,1,0,0,0,578,579,
        7,4,0,0,579,77,1,0,0,0,580,581,3,102,51,0,581,583,5,73,0,0,582,584,
        3,92,46,0,583,582,1,0,0,0,583,584,1,0,0,0,584,585,1,0,0,0,585,601,
        5,74,0,0,586,587,5,34,0,0,587,598,5,55,0,0,588,589,5,84,0,0,589,
        591,5,88,0,0,590,592,3,80,40,0,591,590,1,0,0,0,592,593,1,0,0,0,593,
        591,1,0,0,0,593,594,1,0,0,0,594,595,1,0,0,0,595,596,5,89,0,0,596,
        599,1,0,0,0,597,599,3,80,40,0,598,588,1,0,0,0,598,597,1,0,0,0,599,
        602,1,0,0,0,600,602,5,84,0,0,601,586,1,0,0,0,601,600,1,0,0,0,602,
        79,1,0,0,0,603,608,3,82,41,0,604,608,3,52,26,0,605,608,3,54,27,0,
        606,608,3,84,42,0,607,603,1,0,0,0,607,604,1,0,0,0,607,605,1,0,0,
        0,607,606,1,0,0,0,608,81,1,0,0,0,609,610,3,104,52,0,610,611,5,55,
        0,0,611,613,1,0,0,0,612,609,1,0,0,0,612,613,1,0,0,0,613,614,1,0,
        0,0,614,615,3,102,51,0,615,617,5,73,0,0,616,618,3,92,46,0,617,616,
        1,0,0,0,617,618,1,0,0,0,618,619,1,0,0,0,619,620,5,74,0,0,620,621,
        5,84,0,0,621,83,1,0,0,0,622,623,5,35,0,0,623,624,3,58,29,0,624,625,
        5,84,0,0,625,85,1,0,0,0,626,627,5,36,0,0,627,628,3,58,29,0,628,629,
        5,84,0,0,629,87,1,0,0,0,630,631,5,37,0,0,631,637,3,104,52,0,632,
        634,5,73,0,0,633,635,3,92,46,0,634,633,1,0,0,0,634,635,1,0,0,0,635,
        636,1,0,0,0,636,638,5,74,0,0,637,632,1,0,0,0,637,638,1,0,0,0,638,
        639,1,0,0,0,639,640,5,84,0,0,640,89,1,0,0,0,641,642,5,38,0,0,642,
        643,3,96,48,0,643,644,5,84,0,0,644,91,1,0,0,0,645,650,3,94,47,0,
        646,647,5,53,0,0,647,649,3,94,47,0,648,646,1,0,0,0,649,652,1,0,0,
        0,650,648,1,0,0,0,650,651,1,0,0,0,651,654,1,0,0,0,652,650,1,0,0,
        0,653,655,5,53,0,0,654,653,1,0,0,0,654,655,1,0,0,0,655,93,1,0,0,
        0,656,657,3,104,52,0,657,658,5,55,0,0,658,660,1,0,0,0,659,656,1,
        0,0,0,659,660,1,0,0,0,660,661,1,0,0,0,661,662,3,96,48,0,662,95,1,
        0,0,0,663,664,6,48,-1,0,664,665,7,5,0,0,665,670,3,96,48,10,666,667,
        5,44,0,0,667,670,3,96,48,6,668,670,3,98,49,0,669,663,1,0,0,0,669,
        666,1,0,0,0,669,668,1,0,0,0,670,718,1,0,0,0,671,672,10,9,0,0,672,
        673,7,6,0,0,673,717,3,96,48,10,674,675,10,8,0,0,675,676,7,5,0,0,
        676,717,3,96,48,9,677,678,10,7,0,0,678,679,7,7,0,0,679,717,3,96,
        48,8,680,681,10,5,0,0,681,682,5,42,0,0,682,717,3,96,48,6,683,684,
        10,4,0,0,684,685,5,43,0,0,685,717,3,96,48,5,686,687,10,3,0,0,687,
        688,5,57,0,0,688,717,3,96,48,3,689,690,10,2,0,0,690,691,5,66,0,0,
        691,692,3,96,48,0,692,693,5,55,0,0,693,694,3,96,48,2,694,717,1,0,
        0,0,695,696,10,14,0,0,696,697,5,52,0,0,697,698,7,8,0,0,698,699,5,
        73,0,0,699,700,3,46,23,0,700,701,5,74,0,0,701,717,1,0,0,0,702,703,
        10,13,0,0,703,704,5,52,0,0,704,717,3,104,52,0,705,706,10,12,0,0,
        706,707,5,75,0,0,707,708,3,96,48,0,708,709,5,76,0,0,709,717,1,0,
        0,0,710,711,10,11,0,0,711,713,5,73,0,0,712,714,3,92,46,0,713,712,
        1,0,0,0,713,714,1,0,0,0,714,715,1,0,0,0,715,717,5,74,0,0,716,671,
        1,0,0,0,716,674,1,0,0,0,716,677,1,0,0,0,716,680,1,0,0,0,716,683,
        1,0,0,0,716,686,1,0,0,0,716,689,1,0,0,0,716,695,1,0,0,0,716,702,
        1,0,0,0,716,705,1,0,0,0,716,710,1,0,0,0,717,720,1,0,0,0,718,716,
        1,0,0,0,718,719,1,0,0,0,719,97,1,0,0,0,720,718,1,0,0,0,721,751,5,
        78,0,0,722,751,7,9,0,0,723,751,5,81,0,0,724,751,7,10,0,0,725,751,
        3,100,50,0,726,738,5,75,0,0,727,732,3,96,48,0,728,729,5,53,0,0,729,
        731,3,96,48,0,730,728,1,0,0,0,731,734,1,0,0,0,732,730,1,0,0,0,732,
        733,1,0,0,0,733,736,1,0,0,0,734,732,1,0,0,0,735,737,5,53,0,0,736,
        735,1,0,0,0,736,737,1,0,0,0,737,739,1,0,0,0,738,727,1,0,0,0,738,
        739,1,0,0,0,739,740,1,0,0,0,740,751,5,76,0,0,741,742,3,104,52,0,
        742,743,5,65,0,0,743,744,3,104,52,0,744,751,1,0,0,0,745,751,3,104,
        52,0,746,747,5,73,0,0,747,748,3,96,48,0,748,749,5,74,0,0,749,751,
        1,0,0,0,750,721,1,0,0,0,750,722,1,0,0,0,750,723,1,0,0,0,750,724,
        1,0,0,0,750,725,1,0,0,0,750,726,1,0,0,0,750,741,1,0,0,0,750,745,
        1,0,0,0,750,746,1,0,0,0,751,99,1,0,0,0,752,753,5,75,0,0,753,754,
        3,96,48,0,754,755,5,51,0,0,755,756,3,96,48,0,756,758,5,76,0,0,757,
        759,5,82,0,0,758,757,1,0,0,0,758,759,1,0,0,0,759,101,1,0,0,0,760,
        765,3,104,52,0,761,762,5,52,0,0,762,764,3,104,52,0,763,761,1,0,0,
        0,764,767,1,0,0,0,765,763,1,0,0,0,765,766,1,0,0,0,766,103,1,0,0,
        0,767,765,1,0,0,0,768,770,3,106,53,0,769,768,1,0,0,0,769,770,1,0,
        0,0,770,771,1,0,0,0,771,773,5,54,0,0,772,769,1,0,0,0,772,773,1,0,
        0,0,773,774,1,0,0,0,774,775,3,106,53,0,775,105,1,0,0,0,776,777,7,
        11,0,0,777,107,1,0,0,0,90,111,113,121,136,141,149,154,159,169,174,
        182,187,192,200,205,214,245,249,257,270,283,287,292,298,304,312,
        317,327,330,340,347,350,353,365,372,379,388,393,396,401,407,415,
        420,425,427,438,445,461,464,468,476,480,483,489,494,498,506,515,
        523,528,541,551,558,563,566,574,583,593,598,601,607,612,617,634,
        637,650,654,659,669,713,716,718,732,736,738,750,758,765,769,772
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
                     "'expression'", "'sample'", "'..'", "'.'", "','", "'::'", 
                     "':'", "'->'", "'=>'", "'=='", "'!='", "'<='", "'>='", 
                     "'<'", "'>'", "'='", "'!'", "'?'", "'@'", "'+'", "'-'", 
                     "'*'", "'/'", "'%'", "'('", "')'", "'['", "']'" ]

    symbolicNames = [ "<INVALID>", "IMPORT", "SCENARIO", "ACTION", "ACTOR", 
                      "STRUCT", "ENUM", "TYPE", "UNIT", "GLOBAL", "EXTEND", 
                      "MODIFIER", "NAMESPACE", "USE", "EXPORT", "INHERITS", 
                      "VAR", "KEEP", "DEFAULT", "HARD", "REMOVE_DEFAULT", 
                      "EVENT", "IS", "IF", "DEF", "EXTERNAL", "UNDEFINED", 
                      "COVER", "RECORD", "ON", "DO", "SERIAL", "PARALLEL", 
                      "ONE_OF", "WITH", "UNTIL", "WAIT", "EMIT", "CALL", 
                      "LIST", "OF", "IN", "AND", "OR", "NOT", "TRUE", "FALSE", 
                      "AS", "ONLY", "EXPRESSION", "SAMPLE", "DOUBLEDOT", 
                      "DOT", "COMMA", "DOUBLECOLON", "COLON", "ARROW", "IMPLIES", 
                      "EQ", "NE", "LE", "GE", "LT", "GT", "ASSIGN", "BANG", 
                      "QUESTION", "AT_SIGN", "PLUS", "MINUS", "STAR", "SLASH", 
                      "PERCENT", "LPAREN", "RPAREN", "LBRACK", "RBRACK", 
                      "HexLiteral", "PhysicalLiteral", "FloatLiteral", "IntLiteral", 
                      "StringLiteral", "Identifier", "QuotedIdentifier", 
                      "NEWLINE", "LINE_JOIN", "WS", "COMMENT", "INDENT", 
                      "DEDENT" ]

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
    RULE_exportSpecification = 19
    RULE_scenarioMember = 20
    RULE_fieldDeclaration = 21
    RULE_fieldConstraint = 22
    RULE_typeDeclarator = 23
    RULE_variableDeclaration = 24
    RULE_sampleExpression = 25
    RULE_keepConstraint = 26
    RULE_removeDefault = 27
    RULE_eventDeclaration = 28
    RULE_eventSpecification = 29
    RULE_methodDeclaration = 30
    RULE_parameterList = 31
    RULE_parameter = 32
    RULE_coverageDeclaration = 33
    RULE_onDirective = 34
    RULE_doDirective = 35
    RULE_doMember = 36
    RULE_composition = 37
    RULE_compositionOperator = 38
    RULE_behaviorInvocation = 39
    RULE_behaviorWithMember = 40
    RULE_modifierInvocation = 41
    RULE_untilDirective = 42
    RULE_waitDirective = 43
    RULE_emitDirective = 44
    RULE_callDirective = 45
    RULE_argumentList = 46
    RULE_argument = 47
    RULE_expression = 48
    RULE_primary = 49
    RULE_rangeLiteral = 50
    RULE_dottedName = 51
    RULE_identifier = 52
    RULE_simpleIdentifier = 53

    ruleNames =  [ "oscFile", "importStatement", "declaration", "scenarioDeclaration", 
                   "behaviorName", "inheritance", "actorDeclaration", "structDeclaration", 
                   "structMember", "physicalTypeDeclaration", "unitDeclaration", 
                   "enumDeclaration", "enumMember", "globalDeclaration", 
                   "extendDeclaration", "extensionMember", "modifierDeclaration", 
                   "namespaceStatement", "exportStatement", "exportSpecification", 
                   "scenarioMember", "fieldDeclaration", "fieldConstraint", 
                   "typeDeclarator", "variableDeclaration", "sampleExpression", 
                   "keepConstraint", "removeDefault", "eventDeclaration", 
                   "eventSpecification", "methodDeclaration", "parameterList", 
                   "parameter", "coverageDeclaration", "onDirective", "doDirective", 
                   "doMember", "composition", "compositionOperator", "behaviorInvocation", 
                   "behaviorWithMember", "modifierInvocation", "untilDirective", 
                   "waitDirective", "emitDirective", "callDirective", "argumentList", 
                   "argument", "expression", "primary", "rangeLiteral", 
                   "dottedName", "identifier", "simpleIdentifier" ]

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
    DOUBLECOLON=54
    COLON=55
    ARROW=56
    IMPLIES=57
    EQ=58
    NE=59
    LE=60
    GE=61
    LT=62
    GT=63
    ASSIGN=64
    BANG=65
    QUESTION=66
    AT_SIGN=67
    PLUS=68
    MINUS=69
    STAR=70
    SLASH=71
    PERCENT=72
    LPAREN=73
    RPAREN=74
    LBRACK=75
    RBRACK=76
    HexLiteral=77
    PhysicalLiteral=78
    FloatLiteral=79
    IntLiteral=80
    StringLiteral=81
    Identifier=82
    QuotedIdentifier=83
    NEWLINE=84
    LINE_JOIN=85
    WS=86
    COMMENT=87
    INDENT=88
    DEDENT=89

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
            self.state = 113
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while (((_la) & ~0x3f) == 0 and ((1 << _la) & 24574) != 0) or _la==84:
                self.state = 111
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [1]:
                    self.state = 108
                    self.importStatement()
                    pass
                elif token in [2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 14]:
                    self.state = 109
                    self.declaration()
                    pass
                elif token in [84]:
                    self.state = 110
                    self.match(OpenScenario2Parser.NEWLINE)
                    pass
                else:
                    raise NoViableAltException(self)

                self.state = 115
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 116
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
            self.state = 118
            self.match(OpenScenario2Parser.IMPORT)
            self.state = 121
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [81]:
                self.state = 119
                self.match(OpenScenario2Parser.StringLiteral)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 47, 48, 49, 50, 54, 82, 83]:
                self.state = 120
                self.dottedName()
                pass
            else:
                raise NoViableAltException(self)

            self.state = 123
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
            self.state = 136
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [2, 3]:
                self.enterOuterAlt(localctx, 1)
                self.state = 125
                self.scenarioDeclaration()
                pass
            elif token in [7]:
                self.enterOuterAlt(localctx, 2)
                self.state = 126
                self.physicalTypeDeclaration()
                pass
            elif token in [8]:
                self.enterOuterAlt(localctx, 3)
                self.state = 127
                self.unitDeclaration()
                pass
            elif token in [4]:
                self.enterOuterAlt(localctx, 4)
                self.state = 128
                self.actorDeclaration()
                pass
            elif token in [5]:
                self.enterOuterAlt(localctx, 5)
                self.state = 129
                self.structDeclaration()
                pass
            elif token in [6]:
                self.enterOuterAlt(localctx, 6)
                self.state = 130
                self.enumDeclaration()
                pass
            elif token in [9]:
                self.enterOuterAlt(localctx, 7)
                self.state = 131
                self.globalDeclaration()
                pass
            elif token in [10]:
                self.enterOuterAlt(localctx, 8)
                self.state = 132
                self.extendDeclaration()
                pass
            elif token in [11]:
                self.enterOuterAlt(localctx, 9)
                self.state = 133
                self.modifierDeclaration()
                pass
            elif token in [12]:
                self.enterOuterAlt(localctx, 10)
                self.state = 134
                self.namespaceStatement()
                pass
            elif token in [14]:
                self.enterOuterAlt(localctx, 11)
                self.state = 135
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
            self.state = 138
            localctx.kind = self._input.LT(1)
            _la = self._input.LA(1)
            if not(_la==2 or _la==3):
                localctx.kind = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 139
            self.behaviorName()
            self.state = 141
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 140
                self.inheritance()


            self.state = 154
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [55]:
                self.state = 143
                self.match(OpenScenario2Parser.COLON)
                self.state = 144
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 145
                self.match(OpenScenario2Parser.INDENT)
                self.state = 147 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 146
                    self.scenarioMember()
                    self.state = 149 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127112236892158) != 0) or _la==82 or _la==83):
                        break

                self.state = 151
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [84]:
                self.state = 153
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
            self.state = 159
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,7,self._ctx)
            if la_ == 1:
                self.state = 156
                localctx.actorType = self.identifier()
                self.state = 157
                self.match(OpenScenario2Parser.DOT)


            self.state = 161
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
            self.state = 163
            self.match(OpenScenario2Parser.INHERITS)
            self.state = 164
            localctx.parent = self.behaviorName()
            self.state = 169
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==73:
                self.state = 165
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 166
                localctx.condition = self.expression(0)
                self.state = 167
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
            self.state = 171
            self.match(OpenScenario2Parser.ACTOR)
            self.state = 172
            self.identifier()
            self.state = 174
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 173
                self.inheritance()


            self.state = 187
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [55]:
                self.state = 176
                self.match(OpenScenario2Parser.COLON)
                self.state = 177
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 178
                self.match(OpenScenario2Parser.INDENT)
                self.state = 180 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 179
                    self.structMember()
                    self.state = 182 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127110626279422) != 0) or _la==82 or _la==83):
                        break

                self.state = 184
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [84]:
                self.state = 186
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
            self.state = 189
            self.match(OpenScenario2Parser.STRUCT)
            self.state = 190
            self.identifier()
            self.state = 192
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==15:
                self.state = 191
                self.inheritance()


            self.state = 205
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [55]:
                self.state = 194
                self.match(OpenScenario2Parser.COLON)
                self.state = 195
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 196
                self.match(OpenScenario2Parser.INDENT)
                self.state = 198 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 197
                    self.structMember()
                    self.state = 200 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127110626279422) != 0) or _la==82 or _la==83):
                        break

                self.state = 202
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [84]:
                self.state = 204
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
            self.state = 214
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,15,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 207
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 208
                self.variableDeclaration()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 209
                self.keepConstraint()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 210
                self.removeDefault()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 211
                self.eventDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 212
                self.methodDeclaration()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 213
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
            self.state = 216
            self.match(OpenScenario2Parser.TYPE)
            self.state = 217
            localctx.name = self.identifier()
            self.state = 218
            self.match(OpenScenario2Parser.IS)
            self.state = 219
            localctx.si = self.identifier()
            self.state = 220
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 221
            self.argumentList()
            self.state = 222
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 223
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
            self.state = 225
            self.match(OpenScenario2Parser.UNIT)
            self.state = 226
            localctx.name = self.identifier()
            self.state = 227
            self.match(OpenScenario2Parser.OF)
            self.state = 228
            localctx.type_ = self.identifier()
            self.state = 229
            self.match(OpenScenario2Parser.IS)
            self.state = 230
            localctx.si = self.identifier()
            self.state = 231
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 232
            self.argumentList()
            self.state = 233
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 234
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
            self.state = 236
            self.match(OpenScenario2Parser.ENUM)
            self.state = 237
            self.identifier()
            self.state = 238
            self.match(OpenScenario2Parser.COLON)
            self.state = 239
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 240
            self.enumMember()
            self.state = 245
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,16,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 241
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 242
                    self.enumMember() 
                self.state = 247
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,16,self._ctx)

            self.state = 249
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==53:
                self.state = 248
                self.match(OpenScenario2Parser.COMMA)


            self.state = 251
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 252
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
            self.state = 254
            self.identifier()
            self.state = 257
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==64:
                self.state = 255
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 256
                _la = self._input.LA(1)
                if not(_la==77 or _la==80):
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
            self.state = 259
            self.match(OpenScenario2Parser.GLOBAL)
            self.state = 260
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
            self.state = 292
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,22,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 262
                self.match(OpenScenario2Parser.EXTEND)
                self.state = 263
                self.behaviorName()
                self.state = 264
                self.match(OpenScenario2Parser.COLON)
                self.state = 265
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 266
                self.match(OpenScenario2Parser.INDENT)
                self.state = 268 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 267
                    self.extensionMember()
                    self.state = 270 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127112236892158) != 0) or _la==82 or _la==83):
                        break

                self.state = 272
                self.match(OpenScenario2Parser.DEDENT)
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 274
                self.match(OpenScenario2Parser.EXTEND)
                self.state = 275
                self.behaviorName()
                self.state = 276
                self.match(OpenScenario2Parser.COLON)
                self.state = 277
                self.match(OpenScenario2Parser.LBRACK)
                self.state = 278
                self.enumMember()
                self.state = 283
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,20,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 279
                        self.match(OpenScenario2Parser.COMMA)
                        self.state = 280
                        self.enumMember() 
                    self.state = 285
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,20,self._ctx)

                self.state = 287
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==53:
                    self.state = 286
                    self.match(OpenScenario2Parser.COMMA)


                self.state = 289
                self.match(OpenScenario2Parser.RBRACK)
                self.state = 290
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
            self.state = 298
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,23,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 294
                self.scenarioMember()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 295
                self.enumMember()
                self.state = 296
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
            self.state = 300
            self.match(OpenScenario2Parser.MODIFIER)
            self.state = 301
            self.behaviorName()
            self.state = 304
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==40:
                self.state = 302
                self.match(OpenScenario2Parser.OF)
                self.state = 303
                self.identifier()


            self.state = 317
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [55]:
                self.state = 306
                self.match(OpenScenario2Parser.COLON)
                self.state = 307
                self.match(OpenScenario2Parser.NEWLINE)
                self.state = 308
                self.match(OpenScenario2Parser.INDENT)
                self.state = 310 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 309
                    self.scenarioMember()
                    self.state = 312 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127112236892158) != 0) or _la==82 or _la==83):
                        break

                self.state = 314
                self.match(OpenScenario2Parser.DEDENT)
                pass
            elif token in [84]:
                self.state = 316
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
            self.state = 319
            self.match(OpenScenario2Parser.NAMESPACE)
            self.state = 320
            self.identifier()
            self.state = 330
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==13:
                self.state = 321
                self.match(OpenScenario2Parser.USE)
                self.state = 322
                self.identifier()
                self.state = 327
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==53:
                    self.state = 323
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 324
                    self.identifier()
                    self.state = 329
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)



            self.state = 332
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

        def exportSpecification(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.ExportSpecificationContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.ExportSpecificationContext,i)


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
            self.state = 334
            self.match(OpenScenario2Parser.EXPORT)
            self.state = 335
            self.exportSpecification()
            self.state = 340
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 336
                self.match(OpenScenario2Parser.COMMA)
                self.state = 337
                self.exportSpecification()
                self.state = 342
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 343
            self.match(OpenScenario2Parser.NEWLINE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExportSpecificationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def STAR(self):
            return self.getToken(OpenScenario2Parser.STAR, 0)

        def DOUBLECOLON(self):
            return self.getToken(OpenScenario2Parser.DOUBLECOLON, 0)

        def simpleIdentifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.SimpleIdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_exportSpecification

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExportSpecification" ):
                return visitor.visitExportSpecification(self)
            else:
                return visitor.visitChildren(self)




    def exportSpecification(self):

        localctx = OpenScenario2Parser.ExportSpecificationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 38, self.RULE_exportSpecification)
        self._la = 0 # Token type
        try:
            self.state = 353
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,32,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 345
                self.dottedName()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 350
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20127110205603838) != 0) or _la==82 or _la==83:
                    self.state = 347
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2112711696121854) != 0) or _la==82 or _la==83:
                        self.state = 346
                        self.simpleIdentifier()


                    self.state = 349
                    self.match(OpenScenario2Parser.DOUBLECOLON)


                self.state = 352
                self.match(OpenScenario2Parser.STAR)
                pass


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
        self.enterRule(localctx, 40, self.RULE_scenarioMember)
        try:
            self.state = 365
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,33,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 355
                self.fieldDeclaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 356
                self.variableDeclaration()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 357
                self.keepConstraint()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 358
                self.removeDefault()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 359
                self.eventDeclaration()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 360
                self.methodDeclaration()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 361
                self.coverageDeclaration()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 362
                self.onDirective()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 363
                self.doDirective()
                pass

            elif la_ == 10:
                self.enterOuterAlt(localctx, 10)
                self.state = 364
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
        self.enterRule(localctx, 42, self.RULE_fieldDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 367
            self.identifier()
            self.state = 372
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 368
                self.match(OpenScenario2Parser.COMMA)
                self.state = 369
                self.identifier()
                self.state = 374
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 375
            self.match(OpenScenario2Parser.COLON)
            self.state = 376
            self.typeDeclarator()
            self.state = 379
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==64:
                self.state = 377
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 378
                localctx.defaultValue = self.expression(0)


            self.state = 396
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                self.state = 381
                self.match(OpenScenario2Parser.WITH)
                self.state = 382
                self.match(OpenScenario2Parser.COLON)
                self.state = 393
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [84]:
                    self.state = 383
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 384
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 386 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 385
                        self.fieldConstraint()
                        self.state = 388 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 403832832) != 0)):
                            break

                    self.state = 390
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [17, 20, 27, 28]:
                    self.state = 392
                    self.fieldConstraint()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [84]:
                self.state = 395
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


        def coverageDeclaration(self):
            return self.getTypedRuleContext(OpenScenario2Parser.CoverageDeclarationContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_fieldConstraint

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFieldConstraint" ):
                return visitor.visitFieldConstraint(self)
            else:
                return visitor.visitChildren(self)




    def fieldConstraint(self):

        localctx = OpenScenario2Parser.FieldConstraintContext(self, self._ctx, self.state)
        self.enterRule(localctx, 44, self.RULE_fieldConstraint)
        try:
            self.state = 401
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [17]:
                self.enterOuterAlt(localctx, 1)
                self.state = 398
                self.keepConstraint()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 399
                self.removeDefault()
                pass
            elif token in [27, 28]:
                self.enterOuterAlt(localctx, 3)
                self.state = 400
                self.coverageDeclaration()
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
        self.enterRule(localctx, 46, self.RULE_typeDeclarator)
        try:
            self.state = 407
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,40,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 403
                self.match(OpenScenario2Parser.LIST)
                self.state = 404
                self.match(OpenScenario2Parser.OF)
                self.state = 405
                self.identifier()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 406
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
        self.enterRule(localctx, 48, self.RULE_variableDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 409
            self.match(OpenScenario2Parser.VAR)
            self.state = 410
            self.identifier()
            self.state = 415
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 411
                self.match(OpenScenario2Parser.COMMA)
                self.state = 412
                self.identifier()
                self.state = 417
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 420
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==55:
                self.state = 418
                self.match(OpenScenario2Parser.COLON)
                self.state = 419
                self.typeDeclarator()


            self.state = 427
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==64:
                self.state = 422
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 425
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,43,self._ctx)
                if la_ == 1:
                    self.state = 423
                    self.sampleExpression()
                    pass

                elif la_ == 2:
                    self.state = 424
                    self.expression(0)
                    pass




            self.state = 429
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
        self.enterRule(localctx, 50, self.RULE_sampleExpression)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 431
            self.match(OpenScenario2Parser.SAMPLE)
            self.state = 432
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 433
            self.expression(0)
            self.state = 434
            self.match(OpenScenario2Parser.COMMA)
            self.state = 435
            self.eventSpecification()
            self.state = 438
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==53:
                self.state = 436
                self.match(OpenScenario2Parser.COMMA)
                self.state = 437
                self.expression(0)


            self.state = 440
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
        self.enterRule(localctx, 52, self.RULE_keepConstraint)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 442
            self.match(OpenScenario2Parser.KEEP)
            self.state = 443
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 445
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,46,self._ctx)
            if la_ == 1:
                self.state = 444
                localctx.strength = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==18 or _la==19):
                    localctx.strength = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()


            self.state = 447
            self.expression(0)
            self.state = 448
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 449
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
        self.enterRule(localctx, 54, self.RULE_removeDefault)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 451
            self.match(OpenScenario2Parser.REMOVE_DEFAULT)
            self.state = 452
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 453
            self.expression(0)
            self.state = 454
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 455
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
        self.enterRule(localctx, 56, self.RULE_eventDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 457
            self.match(OpenScenario2Parser.EVENT)
            self.state = 458
            self.identifier()
            self.state = 464
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==73:
                self.state = 459
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 461
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20127110205603838) != 0) or _la==82 or _la==83:
                    self.state = 460
                    self.parameterList()


                self.state = 463
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 468
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==22:
                self.state = 466
                self.match(OpenScenario2Parser.IS)
                self.state = 467
                self.eventSpecification()


            self.state = 470
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
        self.enterRule(localctx, 58, self.RULE_eventSpecification)
        self._la = 0 # Token type
        try:
            self.state = 483
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [67]:
                self.enterOuterAlt(localctx, 1)
                self.state = 472
                self.match(OpenScenario2Parser.AT_SIGN)
                self.state = 473
                self.dottedName()
                self.state = 476
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==47:
                    self.state = 474
                    self.match(OpenScenario2Parser.AS)
                    self.state = 475
                    localctx.alias = self.identifier()


                self.state = 480
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==23:
                    self.state = 478
                    self.match(OpenScenario2Parser.IF)
                    self.state = 479
                    self.expression(0)


                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 44, 45, 46, 47, 48, 49, 50, 54, 68, 69, 73, 75, 77, 78, 79, 80, 81, 82, 83]:
                self.enterOuterAlt(localctx, 2)
                self.state = 482
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
        self.enterRule(localctx, 60, self.RULE_methodDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 485
            self.match(OpenScenario2Parser.DEF)
            self.state = 486
            self.identifier()
            self.state = 487
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 489
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20127110205603838) != 0) or _la==82 or _la==83:
                self.state = 488
                self.parameterList()


            self.state = 491
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 494
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==56:
                self.state = 492
                self.match(OpenScenario2Parser.ARROW)
                self.state = 493
                self.typeDeclarator()


            self.state = 496
            self.match(OpenScenario2Parser.IS)
            self.state = 498
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,55,self._ctx)
            if la_ == 1:
                self.state = 497
                self.match(OpenScenario2Parser.ONLY)


            self.state = 506
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,56,self._ctx)
            if la_ == 1:
                self.state = 500
                self.match(OpenScenario2Parser.EXPRESSION)
                self.state = 501
                self.expression(0)
                pass

            elif la_ == 2:
                self.state = 502
                self.match(OpenScenario2Parser.UNDEFINED)
                pass

            elif la_ == 3:
                self.state = 503
                self.match(OpenScenario2Parser.EXTERNAL)
                self.state = 504
                self.expression(0)
                pass

            elif la_ == 4:
                self.state = 505
                self.expression(0)
                pass


            self.state = 508
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
        self.enterRule(localctx, 62, self.RULE_parameterList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 510
            self.parameter()
            self.state = 515
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==53:
                self.state = 511
                self.match(OpenScenario2Parser.COMMA)
                self.state = 512
                self.parameter()
                self.state = 517
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
        self.enterRule(localctx, 64, self.RULE_parameter)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 518
            self.identifier()
            self.state = 519
            self.match(OpenScenario2Parser.COLON)
            self.state = 520
            self.typeDeclarator()
            self.state = 523
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==64:
                self.state = 521
                self.match(OpenScenario2Parser.ASSIGN)
                self.state = 522
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
        self.enterRule(localctx, 66, self.RULE_coverageDeclaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 525
            _la = self._input.LA(1)
            if not(_la==27 or _la==28):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 526
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 528
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                self.state = 527
                self.argumentList()


            self.state = 530
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 531
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
        self.enterRule(localctx, 68, self.RULE_onDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 533
            self.match(OpenScenario2Parser.ON)
            self.state = 534
            self.eventSpecification()
            self.state = 535
            self.match(OpenScenario2Parser.COLON)
            self.state = 536
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 537
            self.match(OpenScenario2Parser.INDENT)
            self.state = 539 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 538
                self.doMember()
                self.state = 541 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127606274326526) != 0) or _la==82 or _la==83):
                    break

            self.state = 543
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
        self.enterRule(localctx, 70, self.RULE_doDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 545
            self.match(OpenScenario2Parser.DO)
            self.state = 546
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
        self.enterRule(localctx, 72, self.RULE_doMember)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 551
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,61,self._ctx)
            if la_ == 1:
                self.state = 548
                localctx.label = self.identifier()
                self.state = 549
                self.match(OpenScenario2Parser.COLON)


            self.state = 558
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [31, 32, 33]:
                self.state = 553
                self.composition()
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 47, 48, 49, 50, 54, 82, 83]:
                self.state = 554
                self.behaviorInvocation()
                pass
            elif token in [36]:
                self.state = 555
                self.waitDirective()
                pass
            elif token in [37]:
                self.state = 556
                self.emitDirective()
                pass
            elif token in [38]:
                self.state = 557
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
        self.enterRule(localctx, 74, self.RULE_composition)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 560
            self.compositionOperator()
            self.state = 566
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==73:
                self.state = 561
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 563
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                    self.state = 562
                    self.argumentList()


                self.state = 565
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 568
            self.match(OpenScenario2Parser.COLON)
            self.state = 569
            self.match(OpenScenario2Parser.NEWLINE)
            self.state = 570
            self.match(OpenScenario2Parser.INDENT)
            self.state = 572 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 571
                self.doMember()
                self.state = 574 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127606274326526) != 0) or _la==82 or _la==83):
                    break

            self.state = 576
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
        self.enterRule(localctx, 76, self.RULE_compositionOperator)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 578
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
        self.enterRule(localctx, 78, self.RULE_behaviorInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 580
            localctx.target = self.dottedName()
            self.state = 581
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 583
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                self.state = 582
                self.argumentList()


            self.state = 585
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 601
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                self.state = 586
                self.match(OpenScenario2Parser.WITH)
                self.state = 587
                self.match(OpenScenario2Parser.COLON)
                self.state = 598
                self._errHandler.sync(self)
                token = self._input.LA(1)
                if token in [84]:
                    self.state = 588
                    self.match(OpenScenario2Parser.NEWLINE)
                    self.state = 589
                    self.match(OpenScenario2Parser.INDENT)
                    self.state = 591 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while True:
                        self.state = 590
                        self.behaviorWithMember()
                        self.state = 593 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 20127144566521854) != 0) or _la==82 or _la==83):
                            break

                    self.state = 595
                    self.match(OpenScenario2Parser.DEDENT)
                    pass
                elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 17, 19, 20, 21, 25, 26, 35, 39, 40, 47, 48, 49, 50, 54, 82, 83]:
                    self.state = 597
                    self.behaviorWithMember()
                    pass
                else:
                    raise NoViableAltException(self)

                pass
            elif token in [84]:
                self.state = 600
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
        self.enterRule(localctx, 80, self.RULE_behaviorWithMember)
        try:
            self.state = 607
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 47, 48, 49, 50, 54, 82, 83]:
                self.enterOuterAlt(localctx, 1)
                self.state = 603
                self.modifierInvocation()
                pass
            elif token in [17]:
                self.enterOuterAlt(localctx, 2)
                self.state = 604
                self.keepConstraint()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 3)
                self.state = 605
                self.removeDefault()
                pass
            elif token in [35]:
                self.enterOuterAlt(localctx, 4)
                self.state = 606
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
            self.label = None # IdentifierContext
            self.target = None # DottedNameContext

        def LPAREN(self):
            return self.getToken(OpenScenario2Parser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(OpenScenario2Parser.RPAREN, 0)

        def NEWLINE(self):
            return self.getToken(OpenScenario2Parser.NEWLINE, 0)

        def dottedName(self):
            return self.getTypedRuleContext(OpenScenario2Parser.DottedNameContext,0)


        def COLON(self):
            return self.getToken(OpenScenario2Parser.COLON, 0)

        def argumentList(self):
            return self.getTypedRuleContext(OpenScenario2Parser.ArgumentListContext,0)


        def identifier(self):
            return self.getTypedRuleContext(OpenScenario2Parser.IdentifierContext,0)


        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_modifierInvocation

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitModifierInvocation" ):
                return visitor.visitModifierInvocation(self)
            else:
                return visitor.visitChildren(self)




    def modifierInvocation(self):

        localctx = OpenScenario2Parser.ModifierInvocationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 82, self.RULE_modifierInvocation)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 612
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,71,self._ctx)
            if la_ == 1:
                self.state = 609
                localctx.label = self.identifier()
                self.state = 610
                self.match(OpenScenario2Parser.COLON)


            self.state = 614
            localctx.target = self.dottedName()
            self.state = 615
            self.match(OpenScenario2Parser.LPAREN)
            self.state = 617
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                self.state = 616
                self.argumentList()


            self.state = 619
            self.match(OpenScenario2Parser.RPAREN)
            self.state = 620
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
        self.enterRule(localctx, 84, self.RULE_untilDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 622
            self.match(OpenScenario2Parser.UNTIL)
            self.state = 623
            self.eventSpecification()
            self.state = 624
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
        self.enterRule(localctx, 86, self.RULE_waitDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 626
            self.match(OpenScenario2Parser.WAIT)
            self.state = 627
            self.eventSpecification()
            self.state = 628
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
        self.enterRule(localctx, 88, self.RULE_emitDirective)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 630
            self.match(OpenScenario2Parser.EMIT)
            self.state = 631
            self.identifier()
            self.state = 637
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==73:
                self.state = 632
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 634
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                    self.state = 633
                    self.argumentList()


                self.state = 636
                self.match(OpenScenario2Parser.RPAREN)


            self.state = 639
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
        self.enterRule(localctx, 90, self.RULE_callDirective)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 641
            self.match(OpenScenario2Parser.CALL)
            self.state = 642
            self.expression(0)
            self.state = 643
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
        self.enterRule(localctx, 92, self.RULE_argumentList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 645
            self.argument()
            self.state = 650
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,75,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 646
                    self.match(OpenScenario2Parser.COMMA)
                    self.state = 647
                    self.argument() 
                self.state = 652
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,75,self._ctx)

            self.state = 654
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==53:
                self.state = 653
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
        self.enterRule(localctx, 94, self.RULE_argument)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 659
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,77,self._ctx)
            if la_ == 1:
                self.state = 656
                localctx.name = self.identifier()
                self.state = 657
                self.match(OpenScenario2Parser.COLON)


            self.state = 661
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
        _startState = 96
        self.enterRecursionRule(localctx, 96, self.RULE_expression, _p)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 669
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [68, 69]:
                localctx = OpenScenario2Parser.UnaryContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx

                self.state = 664
                localctx.op = self._input.LT(1)
                _la = self._input.LA(1)
                if not(_la==68 or _la==69):
                    localctx.op = self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                self.state = 665
                self.expression(10)
                pass
            elif token in [44]:
                localctx = OpenScenario2Parser.LogicalNotContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 666
                self.match(OpenScenario2Parser.NOT)
                self.state = 667
                self.expression(6)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 19, 21, 25, 26, 39, 40, 45, 46, 47, 48, 49, 50, 54, 73, 75, 77, 78, 79, 80, 81, 82, 83]:
                localctx = OpenScenario2Parser.PrimaryExpressionContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 668
                self.primary()
                pass
            else:
                raise NoViableAltException(self)

            self._ctx.stop = self._input.LT(-1)
            self.state = 718
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,81,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    if self._parseListeners is not None:
                        self.triggerExitRuleEvent()
                    _prevctx = localctx
                    self.state = 716
                    self._errHandler.sync(self)
                    la_ = self._interp.adaptivePredict(self._input,80,self._ctx)
                    if la_ == 1:
                        localctx = OpenScenario2Parser.MultiplicativeContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 671
                        if not self.precpred(self._ctx, 9):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 9)")
                        self.state = 672
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(((((_la - 70)) & ~0x3f) == 0 and ((1 << (_la - 70)) & 7) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 673
                        self.expression(10)
                        pass

                    elif la_ == 2:
                        localctx = OpenScenario2Parser.AdditiveContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 674
                        if not self.precpred(self._ctx, 8):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 8)")
                        self.state = 675
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(_la==68 or _la==69):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 676
                        self.expression(9)
                        pass

                    elif la_ == 3:
                        localctx = OpenScenario2Parser.RelationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 677
                        if not self.precpred(self._ctx, 7):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 7)")
                        self.state = 678
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not((((_la) & ~0x3f) == 0 and ((1 << _la) & -288228177128456192) != 0)):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 679
                        self.expression(8)
                        pass

                    elif la_ == 4:
                        localctx = OpenScenario2Parser.LogicalAndContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 680
                        if not self.precpred(self._ctx, 5):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 5)")
                        self.state = 681
                        self.match(OpenScenario2Parser.AND)
                        self.state = 682
                        self.expression(6)
                        pass

                    elif la_ == 5:
                        localctx = OpenScenario2Parser.LogicalOrContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 683
                        if not self.precpred(self._ctx, 4):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 4)")
                        self.state = 684
                        self.match(OpenScenario2Parser.OR)
                        self.state = 685
                        self.expression(5)
                        pass

                    elif la_ == 6:
                        localctx = OpenScenario2Parser.ImplicationContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 686
                        if not self.precpred(self._ctx, 3):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 3)")
                        self.state = 687
                        self.match(OpenScenario2Parser.IMPLIES)
                        self.state = 688
                        self.expression(3)
                        pass

                    elif la_ == 7:
                        localctx = OpenScenario2Parser.ConditionalContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 689
                        if not self.precpred(self._ctx, 2):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 2)")
                        self.state = 690
                        self.match(OpenScenario2Parser.QUESTION)
                        self.state = 691
                        self.expression(0)
                        self.state = 692
                        self.match(OpenScenario2Parser.COLON)
                        self.state = 693
                        self.expression(2)
                        pass

                    elif la_ == 8:
                        localctx = OpenScenario2Parser.TypeTestContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 695
                        if not self.precpred(self._ctx, 14):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 14)")
                        self.state = 696
                        self.match(OpenScenario2Parser.DOT)
                        self.state = 697
                        localctx.op = self._input.LT(1)
                        _la = self._input.LA(1)
                        if not(_la==22 or _la==47):
                            localctx.op = self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 698
                        self.match(OpenScenario2Parser.LPAREN)
                        self.state = 699
                        self.typeDeclarator()
                        self.state = 700
                        self.match(OpenScenario2Parser.RPAREN)
                        pass

                    elif la_ == 9:
                        localctx = OpenScenario2Parser.MemberAccessContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 702
                        if not self.precpred(self._ctx, 13):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 13)")
                        self.state = 703
                        self.match(OpenScenario2Parser.DOT)
                        self.state = 704
                        self.identifier()
                        pass

                    elif la_ == 10:
                        localctx = OpenScenario2Parser.ElementAccessContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 705
                        if not self.precpred(self._ctx, 12):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 12)")
                        self.state = 706
                        self.match(OpenScenario2Parser.LBRACK)
                        self.state = 707
                        self.expression(0)
                        self.state = 708
                        self.match(OpenScenario2Parser.RBRACK)
                        pass

                    elif la_ == 11:
                        localctx = OpenScenario2Parser.CallContext(self, OpenScenario2Parser.ExpressionContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expression)
                        self.state = 710
                        if not self.precpred(self._ctx, 11):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 11)")
                        self.state = 711
                        self.match(OpenScenario2Parser.LPAREN)
                        self.state = 713
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                            self.state = 712
                            self.argumentList()


                        self.state = 715
                        self.match(OpenScenario2Parser.RPAREN)
                        pass

             
                self.state = 720
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,81,self._ctx)

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
        self.enterRule(localctx, 98, self.RULE_primary)
        self._la = 0 # Token type
        try:
            self.state = 750
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,85,self._ctx)
            if la_ == 1:
                localctx = OpenScenario2Parser.PhysicalLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 721
                self.match(OpenScenario2Parser.PhysicalLiteral)
                pass

            elif la_ == 2:
                localctx = OpenScenario2Parser.NumberLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 722
                _la = self._input.LA(1)
                if not(((((_la - 77)) & ~0x3f) == 0 and ((1 << (_la - 77)) & 13) != 0)):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 3:
                localctx = OpenScenario2Parser.StringLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 723
                self.match(OpenScenario2Parser.StringLiteral)
                pass

            elif la_ == 4:
                localctx = OpenScenario2Parser.BoolLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 724
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
                self.state = 725
                self.rangeLiteral()
                pass

            elif la_ == 6:
                localctx = OpenScenario2Parser.ListLiteralContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 726
                self.match(OpenScenario2Parser.LBRACK)
                self.state = 738
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 20250255507914750) != 0) or ((((_la - 68)) & ~0x3f) == 0 and ((1 << (_la - 68)) & 65187) != 0):
                    self.state = 727
                    self.expression(0)
                    self.state = 732
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,82,self._ctx)
                    while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                        if _alt==1:
                            self.state = 728
                            self.match(OpenScenario2Parser.COMMA)
                            self.state = 729
                            self.expression(0) 
                        self.state = 734
                        self._errHandler.sync(self)
                        _alt = self._interp.adaptivePredict(self._input,82,self._ctx)

                    self.state = 736
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if _la==53:
                        self.state = 735
                        self.match(OpenScenario2Parser.COMMA)




                self.state = 740
                self.match(OpenScenario2Parser.RBRACK)
                pass

            elif la_ == 7:
                localctx = OpenScenario2Parser.EnumValueContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 741
                localctx.enumType = self.identifier()
                self.state = 742
                self.match(OpenScenario2Parser.BANG)
                self.state = 743
                localctx.member = self.identifier()
                pass

            elif la_ == 8:
                localctx = OpenScenario2Parser.NamePrimaryContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 745
                self.identifier()
                pass

            elif la_ == 9:
                localctx = OpenScenario2Parser.ParenthesisedContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 746
                self.match(OpenScenario2Parser.LPAREN)
                self.state = 747
                self.expression(0)
                self.state = 748
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
        self.enterRule(localctx, 100, self.RULE_rangeLiteral)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 752
            self.match(OpenScenario2Parser.LBRACK)
            self.state = 753
            localctx.low = self.expression(0)
            self.state = 754
            self.match(OpenScenario2Parser.DOUBLEDOT)
            self.state = 755
            localctx.high = self.expression(0)
            self.state = 756
            self.match(OpenScenario2Parser.RBRACK)
            self.state = 758
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,86,self._ctx)
            if la_ == 1:
                self.state = 757
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
        self.enterRule(localctx, 102, self.RULE_dottedName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 760
            self.identifier()
            self.state = 765
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==52:
                self.state = 761
                self.match(OpenScenario2Parser.DOT)
                self.state = 762
                self.identifier()
                self.state = 767
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
            self.qualifier = None # SimpleIdentifierContext

        def simpleIdentifier(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(OpenScenario2Parser.SimpleIdentifierContext)
            else:
                return self.getTypedRuleContext(OpenScenario2Parser.SimpleIdentifierContext,i)


        def DOUBLECOLON(self):
            return self.getToken(OpenScenario2Parser.DOUBLECOLON, 0)

        def getRuleIndex(self):
            return OpenScenario2Parser.RULE_identifier

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIdentifier" ):
                return visitor.visitIdentifier(self)
            else:
                return visitor.visitChildren(self)




    def identifier(self):

        localctx = OpenScenario2Parser.IdentifierContext(self, self._ctx, self.state)
        self.enterRule(localctx, 104, self.RULE_identifier)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 772
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,89,self._ctx)
            if la_ == 1:
                self.state = 769
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2112711696121854) != 0) or _la==82 or _la==83:
                    self.state = 768
                    localctx.qualifier = self.simpleIdentifier()


                self.state = 771
                self.match(OpenScenario2Parser.DOUBLECOLON)


            self.state = 774
            self.simpleIdentifier()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SimpleIdentifierContext(ParserRuleContext):
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
            return OpenScenario2Parser.RULE_simpleIdentifier

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSimpleIdentifier" ):
                return visitor.visitSimpleIdentifier(self)
            else:
                return visitor.visitChildren(self)




    def simpleIdentifier(self):

        localctx = OpenScenario2Parser.SimpleIdentifierContext(self, self._ctx, self.state)
        self.enterRule(localctx, 106, self.RULE_simpleIdentifier)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 776
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 2112711696121854) != 0) or _la==82 or _la==83):
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
        self._predicates[48] = self.expression_sempred
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
         




