/* jello-grader-lenient.h: included before every file of a submission built leniently (the
   report names it): the standard headers that another compiler's headers bring in on their
   own, so that std::string, std::vector and the like are declared where a file forgot to
   include them. It declares nothing named pause: the course's jello.h has a global of that
   name. */
#ifdef __cplusplus
#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <list>
#include <map>
#include <string>
#include <vector>
#else
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#endif
