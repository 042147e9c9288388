/* jello-grader-gl-functions-4.h: the GL, GLU and GLUT functions of the grader's GL stand-in
   (jello-grader-gl.h), a part of at most 60000 bytes: each file built into the
   grader stays a string under 64 kB. Made by scripts/make-gl-standins. */
#define glProgramLocalParametersI4ivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERSI4IVNVPROC);
#define glProgramLocalParametersI4uivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERSI4UIVNVPROC);
#define glProgramNamedParameter4dNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMNAMEDPARAMETER4DNVPROC);
#define glProgramNamedParameter4dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMNAMEDPARAMETER4DVNVPROC);
#define glProgramNamedParameter4fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMNAMEDPARAMETER4FNVPROC);
#define glProgramNamedParameter4fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMNAMEDPARAMETER4FVNVPROC);
#define glProgramParameter4dNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETER4DNVPROC);
#define glProgramParameter4dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETER4DVNVPROC);
#define glProgramParameter4fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETER4FNVPROC);
#define glProgramParameter4fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETER4FVNVPROC);
#define glProgramParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETERIPROC);
#define glProgramParameteriARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETERIARBPROC);
#define glProgramParameteriEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETERIEXTPROC);
#define glProgramParameters4dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETERS4DVNVPROC);
#define glProgramParameters4fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPARAMETERS4FVNVPROC);
#define glProgramPathFragmentInputGenNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMPATHFRAGMENTINPUTGENNVPROC);
#define glProgramStringARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMSTRINGARBPROC);
#define glProgramSubroutineParametersuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMSUBROUTINEPARAMETERSUIVNVPROC);
#define glProgramUniform1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1DPROC);
#define glProgramUniform1dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1DEXTPROC);
#define glProgramUniform1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1DVPROC);
#define glProgramUniform1dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1DVEXTPROC);
#define glProgramUniform1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1FPROC);
#define glProgramUniform1fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1FEXTPROC);
#define glProgramUniform1fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1FVPROC);
#define glProgramUniform1fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1FVEXTPROC);
#define glProgramUniform1i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1IPROC);
#define glProgramUniform1i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1I64ARBPROC);
#define glProgramUniform1i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1I64NVPROC);
#define glProgramUniform1i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1I64VARBPROC);
#define glProgramUniform1i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1I64VNVPROC);
#define glProgramUniform1iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1IEXTPROC);
#define glProgramUniform1iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1IVPROC);
#define glProgramUniform1ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1IVEXTPROC);
#define glProgramUniform1ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UIPROC);
#define glProgramUniform1ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UI64ARBPROC);
#define glProgramUniform1ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UI64NVPROC);
#define glProgramUniform1ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UI64VARBPROC);
#define glProgramUniform1ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UI64VNVPROC);
#define glProgramUniform1uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UIEXTPROC);
#define glProgramUniform1uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UIVPROC);
#define glProgramUniform1uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM1UIVEXTPROC);
#define glProgramUniform2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2DPROC);
#define glProgramUniform2dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2DEXTPROC);
#define glProgramUniform2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2DVPROC);
#define glProgramUniform2dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2DVEXTPROC);
#define glProgramUniform2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2FPROC);
#define glProgramUniform2fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2FEXTPROC);
#define glProgramUniform2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2FVPROC);
#define glProgramUniform2fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2FVEXTPROC);
#define glProgramUniform2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2IPROC);
#define glProgramUniform2i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2I64ARBPROC);
#define glProgramUniform2i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2I64NVPROC);
#define glProgramUniform2i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2I64VARBPROC);
#define glProgramUniform2i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2I64VNVPROC);
#define glProgramUniform2iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2IEXTPROC);
#define glProgramUniform2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2IVPROC);
#define glProgramUniform2ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2IVEXTPROC);
#define glProgramUniform2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UIPROC);
#define glProgramUniform2ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UI64ARBPROC);
#define glProgramUniform2ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UI64NVPROC);
#define glProgramUniform2ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UI64VARBPROC);
#define glProgramUniform2ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UI64VNVPROC);
#define glProgramUniform2uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UIEXTPROC);
#define glProgramUniform2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UIVPROC);
#define glProgramUniform2uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM2UIVEXTPROC);
#define glProgramUniform3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3DPROC);
#define glProgramUniform3dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3DEXTPROC);
#define glProgramUniform3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3DVPROC);
#define glProgramUniform3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3DVEXTPROC);
#define glProgramUniform3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3FPROC);
#define glProgramUniform3fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3FEXTPROC);
#define glProgramUniform3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3FVPROC);
#define glProgramUniform3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3FVEXTPROC);
#define glProgramUniform3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3IPROC);
#define glProgramUniform3i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3I64ARBPROC);
#define glProgramUniform3i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3I64NVPROC);
#define glProgramUniform3i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3I64VARBPROC);
#define glProgramUniform3i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3I64VNVPROC);
#define glProgramUniform3iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3IEXTPROC);
#define glProgramUniform3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3IVPROC);
#define glProgramUniform3ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3IVEXTPROC);
#define glProgramUniform3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UIPROC);
#define glProgramUniform3ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UI64ARBPROC);
#define glProgramUniform3ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UI64NVPROC);
#define glProgramUniform3ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UI64VARBPROC);
#define glProgramUniform3ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UI64VNVPROC);
#define glProgramUniform3uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UIEXTPROC);
#define glProgramUniform3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UIVPROC);
#define glProgramUniform3uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM3UIVEXTPROC);
#define glProgramUniform4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4DPROC);
#define glProgramUniform4dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4DEXTPROC);
#define glProgramUniform4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4DVPROC);
#define glProgramUniform4dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4DVEXTPROC);
#define glProgramUniform4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4FPROC);
#define glProgramUniform4fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4FEXTPROC);
#define glProgramUniform4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4FVPROC);
#define glProgramUniform4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4FVEXTPROC);
#define glProgramUniform4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4IPROC);
#define glProgramUniform4i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4I64ARBPROC);
#define glProgramUniform4i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4I64NVPROC);
#define glProgramUniform4i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4I64VARBPROC);
#define glProgramUniform4i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4I64VNVPROC);
#define glProgramUniform4iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4IEXTPROC);
#define glProgramUniform4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4IVPROC);
#define glProgramUniform4ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4IVEXTPROC);
#define glProgramUniform4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UIPROC);
#define glProgramUniform4ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UI64ARBPROC);
#define glProgramUniform4ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UI64NVPROC);
#define glProgramUniform4ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UI64VARBPROC);
#define glProgramUniform4ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UI64VNVPROC);
#define glProgramUniform4uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UIEXTPROC);
#define glProgramUniform4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UIVPROC);
#define glProgramUniform4uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORM4UIVEXTPROC);
#define glProgramUniformHandleui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMHANDLEUI64ARBPROC);
#define glProgramUniformHandleui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMHANDLEUI64NVPROC);
#define glProgramUniformHandleui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMHANDLEUI64VARBPROC);
#define glProgramUniformHandleui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMHANDLEUI64VNVPROC);
#define glProgramUniformMatrix2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2DVPROC);
#define glProgramUniformMatrix2dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2DVEXTPROC);
#define glProgramUniformMatrix2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2FVPROC);
#define glProgramUniformMatrix2fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2FVEXTPROC);
#define glProgramUniformMatrix2x3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X3DVPROC);
#define glProgramUniformMatrix2x3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X3DVEXTPROC);
#define glProgramUniformMatrix2x3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X3FVPROC);
#define glProgramUniformMatrix2x3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X3FVEXTPROC);
#define glProgramUniformMatrix2x4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X4DVPROC);
#define glProgramUniformMatrix2x4dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X4DVEXTPROC);
#define glProgramUniformMatrix2x4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X4FVPROC);
#define glProgramUniformMatrix2x4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX2X4FVEXTPROC);
#define glProgramUniformMatrix3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3DVPROC);
#define glProgramUniformMatrix3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3DVEXTPROC);
#define glProgramUniformMatrix3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3FVPROC);
#define glProgramUniformMatrix3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3FVEXTPROC);
#define glProgramUniformMatrix3x2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X2DVPROC);
#define glProgramUniformMatrix3x2dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X2DVEXTPROC);
#define glProgramUniformMatrix3x2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X2FVPROC);
#define glProgramUniformMatrix3x2fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X2FVEXTPROC);
#define glProgramUniformMatrix3x4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X4DVPROC);
#define glProgramUniformMatrix3x4dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X4DVEXTPROC);
#define glProgramUniformMatrix3x4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X4FVPROC);
#define glProgramUniformMatrix3x4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX3X4FVEXTPROC);
#define glProgramUniformMatrix4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4DVPROC);
#define glProgramUniformMatrix4dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4DVEXTPROC);
#define glProgramUniformMatrix4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4FVPROC);
#define glProgramUniformMatrix4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4FVEXTPROC);
#define glProgramUniformMatrix4x2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X2DVPROC);
#define glProgramUniformMatrix4x2dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X2DVEXTPROC);
#define glProgramUniformMatrix4x2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X2FVPROC);
#define glProgramUniformMatrix4x2fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X2FVEXTPROC);
#define glProgramUniformMatrix4x3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X3DVPROC);
#define glProgramUniformMatrix4x3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X3DVEXTPROC);
#define glProgramUniformMatrix4x3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X3FVPROC);
#define glProgramUniformMatrix4x3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMMATRIX4X3FVEXTPROC);
#define glProgramUniformui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMUI64NVPROC);
#define glProgramUniformui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMUNIFORMUI64VNVPROC);
#define glProgramVertexLimitNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMVERTEXLIMITNVPROC);
#define glProvokingVertex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROVOKINGVERTEXPROC);
#define glProvokingVertexEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROVOKINGVERTEXEXTPROC);
#define glPushAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHATTRIBPROC);
#define glPushClientAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHCLIENTATTRIBPROC);
#define glPushClientAttribDefaultEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHCLIENTATTRIBDEFAULTEXTPROC);
#define glPushDebugGroup(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHDEBUGGROUPPROC);
#define glPushGroupMarkerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHGROUPMARKEREXTPROC);
#define glPushMatrix(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHMATRIXPROC);
#define glPushName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPUSHNAMEPROC);
#define glQueryCounter(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLQUERYCOUNTERPROC);
#define glQueryMatrixxOES(...) (0)
typedef JELLO_GRADER_PROC(PFNGLQUERYMATRIXXOESPROC);
#define glQueryObjectParameteruiAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLQUERYOBJECTPARAMETERUIAMDPROC);
#define glQueryResourceNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLQUERYRESOURCENVPROC);
#define glQueryResourceTagNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLQUERYRESOURCETAGNVPROC);
#define glRasterPos2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2DPROC);
#define glRasterPos2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2DVPROC);
#define glRasterPos2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2FPROC);
#define glRasterPos2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2FVPROC);
#define glRasterPos2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2IPROC);
#define glRasterPos2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2IVPROC);
#define glRasterPos2s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2SPROC);
#define glRasterPos2sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2SVPROC);
#define glRasterPos2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2XOESPROC);
#define glRasterPos2xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS2XVOESPROC);
#define glRasterPos3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3DPROC);
#define glRasterPos3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3DVPROC);
#define glRasterPos3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3FPROC);
#define glRasterPos3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3FVPROC);
#define glRasterPos3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3IPROC);
#define glRasterPos3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3IVPROC);
#define glRasterPos3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3SPROC);
#define glRasterPos3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3SVPROC);
#define glRasterPos3xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3XOESPROC);
#define glRasterPos3xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS3XVOESPROC);
#define glRasterPos4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4DPROC);
#define glRasterPos4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4DVPROC);
#define glRasterPos4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4FPROC);
#define glRasterPos4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4FVPROC);
#define glRasterPos4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4IPROC);
#define glRasterPos4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4IVPROC);
#define glRasterPos4s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4SPROC);
#define glRasterPos4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4SVPROC);
#define glRasterPos4xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4XOESPROC);
#define glRasterPos4xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERPOS4XVOESPROC);
#define glRasterSamplesEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRASTERSAMPLESEXTPROC);
#define glReadBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREADBUFFERPROC);
#define glReadInstrumentsSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREADINSTRUMENTSSGIXPROC);
#define glReadPixels(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREADPIXELSPROC);
#define glReadnPixels(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREADNPIXELSPROC);
#define glReadnPixelsARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREADNPIXELSARBPROC);
#define glRectd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTDPROC);
#define glRectdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTDVPROC);
#define glRectf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTFPROC);
#define glRectfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTFVPROC);
#define glRecti(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTIPROC);
#define glRectiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTIVPROC);
#define glRects(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTSPROC);
#define glRectsv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTSVPROC);
#define glRectxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTXOESPROC);
#define glRectxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRECTXVOESPROC);
#define glReferencePlaneSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREFERENCEPLANESGIXPROC);
#define glReleaseKeyedMutexWin32EXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLRELEASEKEYEDMUTEXWIN32EXTPROC);
#define glReleaseShaderCompiler(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRELEASESHADERCOMPILERPROC);
#define glRenderGpuMaskNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERGPUMASKNVPROC);
#define glRenderMode(...) (0)
typedef JELLO_GRADER_PROC(PFNGLRENDERMODEPROC);
#define glRenderbufferStorage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERBUFFERSTORAGEPROC);
#define glRenderbufferStorageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERBUFFERSTORAGEEXTPROC);
#define glRenderbufferStorageMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC);
#define glRenderbufferStorageMultisampleAdvancedAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEADVANCEDAMDPROC);
#define glRenderbufferStorageMultisampleCoverageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERBUFFERSTORAGEMULTISAMPLECOVERAGENVPROC);
#define glRenderbufferStorageMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEEXTPROC);
#define glReplacementCodePointerSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEPOINTERSUNPROC);
#define glReplacementCodeubSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUBSUNPROC);
#define glReplacementCodeubvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUBVSUNPROC);
#define glReplacementCodeuiColor3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUICOLOR3FVERTEX3FSUNPROC);
#define glReplacementCodeuiColor3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUICOLOR3FVERTEX3FVSUNPROC);
#define glReplacementCodeuiColor4fNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUICOLOR4FNORMAL3FVERTEX3FSUNPROC);
#define glReplacementCodeuiColor4fNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUICOLOR4FNORMAL3FVERTEX3FVSUNPROC);
#define glReplacementCodeuiColor4ubVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUICOLOR4UBVERTEX3FSUNPROC);
#define glReplacementCodeuiColor4ubVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUICOLOR4UBVERTEX3FVSUNPROC);
#define glReplacementCodeuiNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUINORMAL3FVERTEX3FSUNPROC);
#define glReplacementCodeuiNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUINORMAL3FVERTEX3FVSUNPROC);
#define glReplacementCodeuiSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUISUNPROC);
#define glReplacementCodeuiTexCoord2fColor4fNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUITEXCOORD2FCOLOR4FNORMAL3FVERTEX3FSUNPROC);
#define glReplacementCodeuiTexCoord2fColor4fNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUITEXCOORD2FCOLOR4FNORMAL3FVERTEX3FVSUNPROC);
#define glReplacementCodeuiTexCoord2fNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUITEXCOORD2FNORMAL3FVERTEX3FSUNPROC);
#define glReplacementCodeuiTexCoord2fNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUITEXCOORD2FNORMAL3FVERTEX3FVSUNPROC);
#define glReplacementCodeuiTexCoord2fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUITEXCOORD2FVERTEX3FSUNPROC);
#define glReplacementCodeuiTexCoord2fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUITEXCOORD2FVERTEX3FVSUNPROC);
#define glReplacementCodeuiVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUIVERTEX3FSUNPROC);
#define glReplacementCodeuiVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUIVERTEX3FVSUNPROC);
#define glReplacementCodeuivSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUIVSUNPROC);
#define glReplacementCodeusSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUSSUNPROC);
#define glReplacementCodeusvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREPLACEMENTCODEUSVSUNPROC);
#define glRequestResidentProgramsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLREQUESTRESIDENTPROGRAMSNVPROC);
#define glResetHistogram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESETHISTOGRAMPROC);
#define glResetHistogramEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESETHISTOGRAMEXTPROC);
#define glResetMemoryObjectParameterNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESETMEMORYOBJECTPARAMETERNVPROC);
#define glResetMinmax(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESETMINMAXPROC);
#define glResetMinmaxEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESETMINMAXEXTPROC);
#define glResizeBuffersMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESIZEBUFFERSMESAPROC);
#define glResolveDepthValuesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESOLVEDEPTHVALUESNVPROC);
#define glResumeTransformFeedback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESUMETRANSFORMFEEDBACKPROC);
#define glResumeTransformFeedbackNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLRESUMETRANSFORMFEEDBACKNVPROC);
#define glRotated(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLROTATEDPROC);
#define glRotatef(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLROTATEFPROC);
#define glRotatexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLROTATEXOESPROC);
#define glSampleCoverage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLECOVERAGEPROC);
#define glSampleCoverageARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLECOVERAGEARBPROC);
#define glSampleMapATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEMAPATIPROC);
#define glSampleMaskEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEMASKEXTPROC);
#define glSampleMaskIndexedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEMASKINDEXEDNVPROC);
#define glSampleMaskSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEMASKSGISPROC);
#define glSampleMaski(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEMASKIPROC);
#define glSamplePatternEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEPATTERNEXTPROC);
#define glSamplePatternSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLEPATTERNSGISPROC);
#define glSamplerParameterIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLERPARAMETERIIVPROC);
#define glSamplerParameterIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLERPARAMETERIUIVPROC);
#define glSamplerParameterf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLERPARAMETERFPROC);
#define glSamplerParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLERPARAMETERFVPROC);
#define glSamplerParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLERPARAMETERIPROC);
#define glSamplerParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSAMPLERPARAMETERIVPROC);
#define glScaled(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCALEDPROC);
#define glScalef(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCALEFPROC);
#define glScalexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCALEXOESPROC);
#define glScissor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCISSORPROC);
#define glScissorArrayv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCISSORARRAYVPROC);
#define glScissorExclusiveArrayvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCISSOREXCLUSIVEARRAYVNVPROC);
#define glScissorExclusiveNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCISSOREXCLUSIVENVPROC);
#define glScissorIndexed(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCISSORINDEXEDPROC);
#define glScissorIndexedv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSCISSORINDEXEDVPROC);
#define glSecondaryColor3b(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3BPROC);
#define glSecondaryColor3bEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3BEXTPROC);
#define glSecondaryColor3bv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3BVPROC);
#define glSecondaryColor3bvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3BVEXTPROC);
#define glSecondaryColor3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3DPROC);
#define glSecondaryColor3dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3DEXTPROC);
#define glSecondaryColor3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3DVPROC);
#define glSecondaryColor3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3DVEXTPROC);
#define glSecondaryColor3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3FPROC);
#define glSecondaryColor3fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3FEXTPROC);
#define glSecondaryColor3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3FVPROC);
#define glSecondaryColor3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3FVEXTPROC);
#define glSecondaryColor3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3HNVPROC);
#define glSecondaryColor3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3HVNVPROC);
#define glSecondaryColor3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3IPROC);
#define glSecondaryColor3iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3IEXTPROC);
#define glSecondaryColor3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3IVPROC);
#define glSecondaryColor3ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3IVEXTPROC);
#define glSecondaryColor3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3SPROC);
#define glSecondaryColor3sEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3SEXTPROC);
#define glSecondaryColor3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3SVPROC);
#define glSecondaryColor3svEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3SVEXTPROC);
#define glSecondaryColor3ub(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UBPROC);
#define glSecondaryColor3ubEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UBEXTPROC);
#define glSecondaryColor3ubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UBVPROC);
#define glSecondaryColor3ubvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UBVEXTPROC);
#define glSecondaryColor3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UIPROC);
#define glSecondaryColor3uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UIEXTPROC);
#define glSecondaryColor3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UIVPROC);
#define glSecondaryColor3uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3UIVEXTPROC);
#define glSecondaryColor3us(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3USPROC);
#define glSecondaryColor3usEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3USEXTPROC);
#define glSecondaryColor3usv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3USVPROC);
#define glSecondaryColor3usvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLOR3USVEXTPROC);
#define glSecondaryColorFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLORFORMATNVPROC);
#define glSecondaryColorP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLORP3UIPROC);
#define glSecondaryColorP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLORP3UIVPROC);
#define glSecondaryColorPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLORPOINTERPROC);
#define glSecondaryColorPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLORPOINTEREXTPROC);
#define glSecondaryColorPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSECONDARYCOLORPOINTERLISTIBMPROC);
#define glSelectBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSELECTBUFFERPROC);
#define glSelectPerfMonitorCountersAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSELECTPERFMONITORCOUNTERSAMDPROC);
#define glSemaphoreParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSEMAPHOREPARAMETERIVNVPROC);
#define glSemaphoreParameterui64vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSEMAPHOREPARAMETERUI64VEXTPROC);
#define glSeparableFilter2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSEPARABLEFILTER2DPROC);
#define glSeparableFilter2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSEPARABLEFILTER2DEXTPROC);
#define glSetFenceAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSETFENCEAPPLEPROC);
#define glSetFenceNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSETFENCENVPROC);
#define glSetFragmentShaderConstantATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSETFRAGMENTSHADERCONSTANTATIPROC);
#define glSetInvariantEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSETINVARIANTEXTPROC);
#define glSetLocalConstantEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSETLOCALCONSTANTEXTPROC);
#define glSetMultisamplefvAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSETMULTISAMPLEFVAMDPROC);
#define glShadeModel(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADEMODELPROC);
#define glShaderBinary(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADERBINARYPROC);
#define glShaderOp1EXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADEROP1EXTPROC);
#define glShaderOp2EXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADEROP2EXTPROC);
#define glShaderOp3EXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADEROP3EXTPROC);
#define glShaderSource(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADERSOURCEPROC);
#define glShaderSourceARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADERSOURCEARBPROC);
#define glShaderStorageBlockBinding(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADERSTORAGEBLOCKBINDINGPROC);
#define glShadingRateImageBarrierNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADINGRATEIMAGEBARRIERNVPROC);
#define glShadingRateImagePaletteNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADINGRATEIMAGEPALETTENVPROC);
#define glShadingRateSampleOrderCustomNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADINGRATESAMPLEORDERCUSTOMNVPROC);
#define glShadingRateSampleOrderNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHADINGRATESAMPLEORDERNVPROC);
#define glSharpenTexFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSHARPENTEXFUNCSGISPROC);
#define glSignalSemaphoreEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSIGNALSEMAPHOREEXTPROC);
#define glSignalSemaphoreui64NVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSIGNALSEMAPHOREUI64NVXPROC);
#define glSignalVkFenceNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSIGNALVKFENCENVPROC);
#define glSignalVkSemaphoreNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSIGNALVKSEMAPHORENVPROC);
#define glSpecializeShader(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSPECIALIZESHADERPROC);
#define glSpecializeShaderARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSPECIALIZESHADERARBPROC);
#define glSpriteParameterfSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSPRITEPARAMETERFSGIXPROC);
#define glSpriteParameterfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSPRITEPARAMETERFVSGIXPROC);
#define glSpriteParameteriSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSPRITEPARAMETERISGIXPROC);
#define glSpriteParameterivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSPRITEPARAMETERIVSGIXPROC);
#define glStartInstrumentsSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTARTINSTRUMENTSSGIXPROC);
#define glStateCaptureNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTATECAPTURENVPROC);
#define glStencilClearTagEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILCLEARTAGEXTPROC);
#define glStencilFillPathInstancedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILFILLPATHINSTANCEDNVPROC);
#define glStencilFillPathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILFILLPATHNVPROC);
#define glStencilFunc(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILFUNCPROC);
#define glStencilFuncSeparate(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILFUNCSEPARATEPROC);
#define glStencilFuncSeparateATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILFUNCSEPARATEATIPROC);
#define glStencilMask(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILMASKPROC);
#define glStencilMaskSeparate(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILMASKSEPARATEPROC);
#define glStencilOp(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILOPPROC);
#define glStencilOpSeparate(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILOPSEPARATEPROC);
#define glStencilOpSeparateATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILOPSEPARATEATIPROC);
#define glStencilOpValueAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILOPVALUEAMDPROC);
#define glStencilStrokePathInstancedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILSTROKEPATHINSTANCEDNVPROC);
#define glStencilStrokePathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILSTROKEPATHNVPROC);
#define glStencilThenCoverFillPathInstancedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILTHENCOVERFILLPATHINSTANCEDNVPROC);
#define glStencilThenCoverFillPathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILTHENCOVERFILLPATHNVPROC);
#define glStencilThenCoverStrokePathInstancedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILTHENCOVERSTROKEPATHINSTANCEDNVPROC);
#define glStencilThenCoverStrokePathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTENCILTHENCOVERSTROKEPATHNVPROC);
#define glStopInstrumentsSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTOPINSTRUMENTSSGIXPROC);
#define glStringMarkerGREMEDY(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSTRINGMARKERGREMEDYPROC);
#define glSubpixelPrecisionBiasNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSUBPIXELPRECISIONBIASNVPROC);
#define glSwizzleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSWIZZLEEXTPROC);
#define glSyncTextureINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLSYNCTEXTUREINTELPROC);
#define glTagSampleBufferSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTAGSAMPLEBUFFERSGIXPROC);
#define glTangent3bEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3BEXTPROC);
#define glTangent3bvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3BVEXTPROC);
#define glTangent3dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3DEXTPROC);
#define glTangent3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3DVEXTPROC);
#define glTangent3fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3FEXTPROC);
#define glTangent3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3FVEXTPROC);
#define glTangent3iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3IEXTPROC);
#define glTangent3ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3IVEXTPROC);
#define glTangent3sEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3SEXTPROC);
#define glTangent3svEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENT3SVEXTPROC);
#define glTangentPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTANGENTPOINTEREXTPROC);
#define glTbufferMask3DFX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTBUFFERMASK3DFXPROC);
#define glTessellationFactorAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTESSELLATIONFACTORAMDPROC);
#define glTessellationModeAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTESSELLATIONMODEAMDPROC);
#define glTestFenceAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLTESTFENCEAPPLEPROC);
#define glTestFenceNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLTESTFENCENVPROC);
#define glTestObjectAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLTESTOBJECTAPPLEPROC);
#define glTexAttachMemoryNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXATTACHMEMORYNVPROC);
#define glTexBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXBUFFERPROC);
#define glTexBufferARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXBUFFERARBPROC);
#define glTexBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXBUFFEREXTPROC);
#define glTexBufferRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXBUFFERRANGEPROC);
#define glTexBumpParameterfvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXBUMPPARAMETERFVATIPROC);
#define glTexBumpParameterivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXBUMPPARAMETERIVATIPROC);
#define glTexCoord1bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1BOESPROC);
#define glTexCoord1bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1BVOESPROC);
#define glTexCoord1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1DPROC);
#define glTexCoord1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1DVPROC);
#define glTexCoord1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1FPROC);
#define glTexCoord1fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1FVPROC);
#define glTexCoord1hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1HNVPROC);
#define glTexCoord1hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1HVNVPROC);
#define glTexCoord1i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1IPROC);
#define glTexCoord1iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1IVPROC);
#define glTexCoord1s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1SPROC);
#define glTexCoord1sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1SVPROC);
#define glTexCoord1xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1XOESPROC);
#define glTexCoord1xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD1XVOESPROC);
#define glTexCoord2bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2BOESPROC);
#define glTexCoord2bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2BVOESPROC);
#define glTexCoord2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2DPROC);
#define glTexCoord2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2DVPROC);
#define glTexCoord2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FPROC);
#define glTexCoord2fColor3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FCOLOR3FVERTEX3FSUNPROC);
#define glTexCoord2fColor3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FCOLOR3FVERTEX3FVSUNPROC);
#define glTexCoord2fColor4fNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FCOLOR4FNORMAL3FVERTEX3FSUNPROC);
#define glTexCoord2fColor4fNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FCOLOR4FNORMAL3FVERTEX3FVSUNPROC);
#define glTexCoord2fColor4ubVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FCOLOR4UBVERTEX3FSUNPROC);
#define glTexCoord2fColor4ubVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FCOLOR4UBVERTEX3FVSUNPROC);
#define glTexCoord2fNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FNORMAL3FVERTEX3FSUNPROC);
#define glTexCoord2fNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FNORMAL3FVERTEX3FVSUNPROC);
#define glTexCoord2fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FVERTEX3FSUNPROC);
#define glTexCoord2fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FVERTEX3FVSUNPROC);
#define glTexCoord2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2FVPROC);
#define glTexCoord2hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2HNVPROC);
#define glTexCoord2hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2HVNVPROC);
#define glTexCoord2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2IPROC);
#define glTexCoord2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2IVPROC);
#define glTexCoord2s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2SPROC);
#define glTexCoord2sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2SVPROC);
#define glTexCoord2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2XOESPROC);
#define glTexCoord2xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD2XVOESPROC);
#define glTexCoord3bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3BOESPROC);
#define glTexCoord3bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3BVOESPROC);
#define glTexCoord3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3DPROC);
#define glTexCoord3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3DVPROC);
#define glTexCoord3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3FPROC);
#define glTexCoord3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3FVPROC);
#define glTexCoord3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3HNVPROC);
#define glTexCoord3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3HVNVPROC);
#define glTexCoord3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3IPROC);
#define glTexCoord3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3IVPROC);
#define glTexCoord3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3SPROC);
#define glTexCoord3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3SVPROC);
#define glTexCoord3xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3XOESPROC);
#define glTexCoord3xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD3XVOESPROC);
#define glTexCoord4bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4BOESPROC);
#define glTexCoord4bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4BVOESPROC);
#define glTexCoord4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4DPROC);
#define glTexCoord4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4DVPROC);
#define glTexCoord4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4FPROC);
#define glTexCoord4fColor4fNormal3fVertex4fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4FCOLOR4FNORMAL3FVERTEX4FSUNPROC);
#define glTexCoord4fColor4fNormal3fVertex4fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4FCOLOR4FNORMAL3FVERTEX4FVSUNPROC);
#define glTexCoord4fVertex4fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4FVERTEX4FSUNPROC);
#define glTexCoord4fVertex4fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4FVERTEX4FVSUNPROC);
#define glTexCoord4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4FVPROC);
#define glTexCoord4hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4HNVPROC);
#define glTexCoord4hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4HVNVPROC);
#define glTexCoord4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4IPROC);
#define glTexCoord4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4IVPROC);
#define glTexCoord4s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4SPROC);
#define glTexCoord4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4SVPROC);
#define glTexCoord4xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4XOESPROC);
#define glTexCoord4xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORD4XVOESPROC);
#define glTexCoordFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDFORMATNVPROC);
#define glTexCoordP1ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP1UIPROC);
#define glTexCoordP1uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP1UIVPROC);
#define glTexCoordP2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP2UIPROC);
#define glTexCoordP2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP2UIVPROC);
#define glTexCoordP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP3UIPROC);
#define glTexCoordP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP3UIVPROC);
#define glTexCoordP4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP4UIPROC);
#define glTexCoordP4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDP4UIVPROC);
#define glTexCoordPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDPOINTERPROC);
#define glTexCoordPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDPOINTEREXTPROC);
#define glTexCoordPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDPOINTERLISTIBMPROC);
#define glTexCoordPointervINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXCOORDPOINTERVINTELPROC);
#define glTexEnvf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXENVFPROC);
#define glTexEnvfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXENVFVPROC);
#define glTexEnvi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXENVIPROC);
#define glTexEnviv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXENVIVPROC);
#define glTexEnvxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXENVXOESPROC);
#define glTexEnvxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXENVXVOESPROC);
#define glTexFilterFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXFILTERFUNCSGISPROC);
#define glTexGend(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENDPROC);
#define glTexGendv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENDVPROC);
#define glTexGenf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENFPROC);
#define glTexGenfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENFVPROC);
#define glTexGeni(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENIPROC);
#define glTexGeniv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENIVPROC);
#define glTexGenxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENXOESPROC);
#define glTexGenxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXGENXVOESPROC);
#define glTexImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE1DPROC);
#define glTexImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE2DPROC);
#define glTexImage2DMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE2DMULTISAMPLEPROC);
#define glTexImage2DMultisampleCoverageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE2DMULTISAMPLECOVERAGENVPROC);
#define glTexImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE3DPROC);
#define glTexImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE3DEXTPROC);
#define glTexImage3DMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE3DMULTISAMPLEPROC);
#define glTexImage3DMultisampleCoverageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE3DMULTISAMPLECOVERAGENVPROC);
#define glTexImage4DSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXIMAGE4DSGISPROC);
#define glTexPageCommitmentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPAGECOMMITMENTARBPROC);
#define glTexPageCommitmentMemNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPAGECOMMITMENTMEMNVPROC);
#define glTexParameterIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERIIVPROC);
#define glTexParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERIIVEXTPROC);
#define glTexParameterIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERIUIVPROC);
#define glTexParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERIUIVEXTPROC);
#define glTexParameterf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERFPROC);
#define glTexParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERFVPROC);
#define glTexParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERIPROC);
#define glTexParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERIVPROC);
#define glTexParameterxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERXOESPROC);
#define glTexParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXPARAMETERXVOESPROC);
#define glTexRenderbufferNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXRENDERBUFFERNVPROC);
#define glTexStorage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE1DPROC);
#define glTexStorage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE1DEXTPROC);
#define glTexStorage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE2DPROC);
#define glTexStorage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE2DEXTPROC);
#define glTexStorage2DMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE2DMULTISAMPLEPROC);
#define glTexStorage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE3DPROC);
#define glTexStorage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE3DEXTPROC);
#define glTexStorage3DMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGE3DMULTISAMPLEPROC);
#define glTexStorageMem1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGEMEM1DEXTPROC);
#define glTexStorageMem2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGEMEM2DEXTPROC);
#define glTexStorageMem2DMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGEMEM2DMULTISAMPLEEXTPROC);
#define glTexStorageMem3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGEMEM3DEXTPROC);
#define glTexStorageMem3DMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGEMEM3DMULTISAMPLEEXTPROC);
#define glTexStorageSparseAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSTORAGESPARSEAMDPROC);
#define glTexSubImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE1DPROC);
#define glTexSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE1DEXTPROC);
#define glTexSubImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE2DPROC);
#define glTexSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE2DEXTPROC);
#define glTexSubImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE3DPROC);
#define glTexSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE3DEXTPROC);
#define glTexSubImage4DSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXSUBIMAGE4DSGISPROC);
#define glTextureAttachMemoryNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREATTACHMEMORYNVPROC);
#define glTextureBarrier(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREBARRIERPROC);
#define glTextureBarrierNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREBARRIERNVPROC);
#define glTextureBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREBUFFERPROC);
#define glTextureBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREBUFFEREXTPROC);
#define glTextureBufferRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREBUFFERRANGEPROC);
#define glTextureBufferRangeEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREBUFFERRANGEEXTPROC);
#define glTextureColorMaskSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURECOLORMASKSGISPROC);
#define glTextureImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE1DEXTPROC);
#define glTextureImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE2DEXTPROC);
#define glTextureImage2DMultisampleCoverageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE2DMULTISAMPLECOVERAGENVPROC);
#define glTextureImage2DMultisampleNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE2DMULTISAMPLENVPROC);
#define glTextureImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE3DEXTPROC);
#define glTextureImage3DMultisampleCoverageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE3DMULTISAMPLECOVERAGENVPROC);
#define glTextureImage3DMultisampleNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREIMAGE3DMULTISAMPLENVPROC);
#define glTextureLightEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURELIGHTEXTPROC);
#define glTextureMaterialEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREMATERIALEXTPROC);
#define glTextureNormalEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURENORMALEXTPROC);
#define glTexturePageCommitmentEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPAGECOMMITMENTEXTPROC);
#define glTexturePageCommitmentMemNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPAGECOMMITMENTMEMNVPROC);
#define glTextureParameterIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIIVPROC);
#define glTextureParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIIVEXTPROC);
#define glTextureParameterIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIUIVPROC);
#define glTextureParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIUIVEXTPROC);
#define glTextureParameterf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERFPROC);
#define glTextureParameterfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERFEXTPROC);
#define glTextureParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERFVPROC);
#define glTextureParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERFVEXTPROC);
#define glTextureParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIPROC);
#define glTextureParameteriEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIEXTPROC);
#define glTextureParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIVPROC);
#define glTextureParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREPARAMETERIVEXTPROC);
#define glTextureRangeAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURERANGEAPPLEPROC);
#define glTextureRenderbufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURERENDERBUFFEREXTPROC);
#define glTextureStorage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE1DPROC);
#define glTextureStorage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE1DEXTPROC);
#define glTextureStorage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE2DPROC);
#define glTextureStorage2DEXT(...) ((void)0)
