/* jello-grader-gl-functions-2.h: the GL, GLU and GLUT functions of the grader's GL stand-in
   (jello-grader-gl.h), a part of at most 60000 bytes: each file built into the
   grader stays a string under 64 kB. Made by scripts/make-gl-standins. */
typedef JELLO_GRADER_PROC(PFNGLFLUSHSTATICDATAIBMPROC);
#define glFlushVertexArrayRangeAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHVERTEXARRAYRANGEAPPLEPROC);
#define glFlushVertexArrayRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHVERTEXARRAYRANGENVPROC);
#define glFogCoordFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDFORMATNVPROC);
#define glFogCoordPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDPOINTERPROC);
#define glFogCoordPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDPOINTEREXTPROC);
#define glFogCoordPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDPOINTERLISTIBMPROC);
#define glFogCoordd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDDPROC);
#define glFogCoorddEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDDEXTPROC);
#define glFogCoorddv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDDVPROC);
#define glFogCoorddvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDDVEXTPROC);
#define glFogCoordf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDFPROC);
#define glFogCoordfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDFEXTPROC);
#define glFogCoordfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDFVPROC);
#define glFogCoordfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDFVEXTPROC);
#define glFogCoordhNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDHNVPROC);
#define glFogCoordhvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGCOORDHVNVPROC);
#define glFogFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGFUNCSGISPROC);
#define glFogf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGFPROC);
#define glFogfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGFVPROC);
#define glFogi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGIPROC);
#define glFogiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGIVPROC);
#define glFogxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGXOESPROC);
#define glFogxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFOGXVOESPROC);
#define glFragmentColorMaterialSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTCOLORMATERIALSGIXPROC);
#define glFragmentCoverageColorNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTCOVERAGECOLORNVPROC);
#define glFragmentLightModelfSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTMODELFSGIXPROC);
#define glFragmentLightModelfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTMODELFVSGIXPROC);
#define glFragmentLightModeliSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTMODELISGIXPROC);
#define glFragmentLightModelivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTMODELIVSGIXPROC);
#define glFragmentLightfSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTFSGIXPROC);
#define glFragmentLightfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTFVSGIXPROC);
#define glFragmentLightiSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTISGIXPROC);
#define glFragmentLightivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTLIGHTIVSGIXPROC);
#define glFragmentMaterialfSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTMATERIALFSGIXPROC);
#define glFragmentMaterialfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTMATERIALFVSGIXPROC);
#define glFragmentMaterialiSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTMATERIALISGIXPROC);
#define glFragmentMaterialivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAGMENTMATERIALIVSGIXPROC);
#define glFrameTerminatorGREMEDY(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMETERMINATORGREMEDYPROC);
#define glFrameZoomSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEZOOMSGIXPROC);
#define glFramebufferDrawBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERDRAWBUFFEREXTPROC);
#define glFramebufferDrawBuffersEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERDRAWBUFFERSEXTPROC);
#define glFramebufferFetchBarrierEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERFETCHBARRIEREXTPROC);
#define glFramebufferParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERPARAMETERIPROC);
#define glFramebufferParameteriMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERPARAMETERIMESAPROC);
#define glFramebufferReadBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERREADBUFFEREXTPROC);
#define glFramebufferRenderbuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERRENDERBUFFERPROC);
#define glFramebufferRenderbufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERRENDERBUFFEREXTPROC);
#define glFramebufferSampleLocationsfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERSAMPLELOCATIONSFVARBPROC);
#define glFramebufferSampleLocationsfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERSAMPLELOCATIONSFVNVPROC);
#define glFramebufferSamplePositionsfvAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERSAMPLEPOSITIONSFVAMDPROC);
#define glFramebufferTexture(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTUREPROC);
#define glFramebufferTexture1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURE1DPROC);
#define glFramebufferTexture1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURE1DEXTPROC);
#define glFramebufferTexture2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURE2DPROC);
#define glFramebufferTexture2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURE2DEXTPROC);
#define glFramebufferTexture3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURE3DPROC);
#define glFramebufferTexture3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURE3DEXTPROC);
#define glFramebufferTextureARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTUREARBPROC);
#define glFramebufferTextureEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTUREEXTPROC);
#define glFramebufferTextureFaceARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTUREFACEARBPROC);
#define glFramebufferTextureFaceEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTUREFACEEXTPROC);
#define glFramebufferTextureLayer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURELAYERPROC);
#define glFramebufferTextureLayerARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURELAYERARBPROC);
#define glFramebufferTextureLayerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTURELAYEREXTPROC);
#define glFramebufferTextureMultiviewOVR(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRAMEBUFFERTEXTUREMULTIVIEWOVRPROC);
#define glFreeObjectBufferATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFREEOBJECTBUFFERATIPROC);
#define glFrontFace(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRONTFACEPROC);
#define glFrustum(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRUSTUMPROC);
#define glFrustumfOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRUSTUMFOESPROC);
#define glFrustumxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFRUSTUMXOESPROC);
#define glGenAsyncMarkersSGIX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGENASYNCMARKERSSGIXPROC);
#define glGenBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENBUFFERSPROC);
#define glGenBuffersARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENBUFFERSARBPROC);
#define glGenFencesAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENFENCESAPPLEPROC);
#define glGenFencesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENFENCESNVPROC);
#define glGenFragmentShadersATI(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGENFRAGMENTSHADERSATIPROC);
#define glGenFramebuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENFRAMEBUFFERSPROC);
#define glGenFramebuffersEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENFRAMEBUFFERSEXTPROC);
#define glGenLists(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGENLISTSPROC);
#define glGenNamesAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENNAMESAMDPROC);
#define glGenOcclusionQueriesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENOCCLUSIONQUERIESNVPROC);
#define glGenPathsNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGENPATHSNVPROC);
#define glGenPerfMonitorsAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENPERFMONITORSAMDPROC);
#define glGenProgramPipelines(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENPROGRAMPIPELINESPROC);
#define glGenProgramsARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENPROGRAMSARBPROC);
#define glGenProgramsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENPROGRAMSNVPROC);
#define glGenQueries(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENQUERIESPROC);
#define glGenQueriesARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENQUERIESARBPROC);
#define glGenQueryResourceTagNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENQUERYRESOURCETAGNVPROC);
#define glGenRenderbuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENRENDERBUFFERSPROC);
#define glGenRenderbuffersEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENRENDERBUFFERSEXTPROC);
#define glGenSamplers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENSAMPLERSPROC);
#define glGenSemaphoresEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENSEMAPHORESEXTPROC);
#define glGenSymbolsEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGENSYMBOLSEXTPROC);
#define glGenTextures(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENTEXTURESPROC);
#define glGenTexturesEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENTEXTURESEXTPROC);
#define glGenTransformFeedbacks(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENTRANSFORMFEEDBACKSPROC);
#define glGenTransformFeedbacksNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENTRANSFORMFEEDBACKSNVPROC);
#define glGenVertexArrays(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENVERTEXARRAYSPROC);
#define glGenVertexArraysAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENVERTEXARRAYSAPPLEPROC);
#define glGenVertexShadersEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGENVERTEXSHADERSEXTPROC);
#define glGenerateMipmap(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENERATEMIPMAPPROC);
#define glGenerateMipmapEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENERATEMIPMAPEXTPROC);
#define glGenerateMultiTexMipmapEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENERATEMULTITEXMIPMAPEXTPROC);
#define glGenerateTextureMipmap(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENERATETEXTUREMIPMAPPROC);
#define glGenerateTextureMipmapEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGENERATETEXTUREMIPMAPEXTPROC);
#define glGetActiveAtomicCounterBufferiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEATOMICCOUNTERBUFFERIVPROC);
#define glGetActiveAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEATTRIBPROC);
#define glGetActiveAttribARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEATTRIBARBPROC);
#define glGetActiveSubroutineName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVESUBROUTINENAMEPROC);
#define glGetActiveSubroutineUniformName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVESUBROUTINEUNIFORMNAMEPROC);
#define glGetActiveSubroutineUniformiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVESUBROUTINEUNIFORMIVPROC);
#define glGetActiveUniform(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEUNIFORMPROC);
#define glGetActiveUniformARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEUNIFORMARBPROC);
#define glGetActiveUniformBlockName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEUNIFORMBLOCKNAMEPROC);
#define glGetActiveUniformBlockiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEUNIFORMBLOCKIVPROC);
#define glGetActiveUniformName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEUNIFORMNAMEPROC);
#define glGetActiveUniformsiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEUNIFORMSIVPROC);
#define glGetActiveVaryingNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETACTIVEVARYINGNVPROC);
#define glGetArrayObjectfvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETARRAYOBJECTFVATIPROC);
#define glGetArrayObjectivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETARRAYOBJECTIVATIPROC);
#define glGetAttachedObjectsARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETATTACHEDOBJECTSARBPROC);
#define glGetAttachedShaders(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETATTACHEDSHADERSPROC);
#define glGetAttribLocation(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETATTRIBLOCATIONPROC);
#define glGetAttribLocationARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETATTRIBLOCATIONARBPROC);
#define glGetBooleanIndexedvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBOOLEANINDEXEDVEXTPROC);
#define glGetBooleani_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBOOLEANI_VPROC);
#define glGetBooleanv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBOOLEANVPROC);
#define glGetBufferParameteri64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERPARAMETERI64VPROC);
#define glGetBufferParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERPARAMETERIVPROC);
#define glGetBufferParameterivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERPARAMETERIVARBPROC);
#define glGetBufferParameterui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERPARAMETERUI64VNVPROC);
#define glGetBufferPointerv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERPOINTERVPROC);
#define glGetBufferPointervARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERPOINTERVARBPROC);
#define glGetBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERSUBDATAPROC);
#define glGetBufferSubDataARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETBUFFERSUBDATAARBPROC);
#define glGetClipPlane(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCLIPPLANEPROC);
#define glGetClipPlanefOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCLIPPLANEFOESPROC);
#define glGetClipPlanexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCLIPPLANEXOESPROC);
#define glGetColorTable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPROC);
#define glGetColorTableEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEEXTPROC);
#define glGetColorTableParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPARAMETERFVPROC);
#define glGetColorTableParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPARAMETERFVEXTPROC);
#define glGetColorTableParameterfvSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPARAMETERFVSGIPROC);
#define glGetColorTableParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPARAMETERIVPROC);
#define glGetColorTableParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPARAMETERIVEXTPROC);
#define glGetColorTableParameterivSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLEPARAMETERIVSGIPROC);
#define glGetColorTableSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOLORTABLESGIPROC);
#define glGetCombinerInputParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMBINERINPUTPARAMETERFVNVPROC);
#define glGetCombinerInputParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMBINERINPUTPARAMETERIVNVPROC);
#define glGetCombinerOutputParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMBINEROUTPUTPARAMETERFVNVPROC);
#define glGetCombinerOutputParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMBINEROUTPUTPARAMETERIVNVPROC);
#define glGetCombinerStageParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMBINERSTAGEPARAMETERFVNVPROC);
#define glGetCommandHeaderNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMMANDHEADERNVPROC);
#define glGetCompressedMultiTexImageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMPRESSEDMULTITEXIMAGEEXTPROC);
#define glGetCompressedTexImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMPRESSEDTEXIMAGEPROC);
#define glGetCompressedTexImageARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMPRESSEDTEXIMAGEARBPROC);
#define glGetCompressedTextureImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMPRESSEDTEXTUREIMAGEPROC);
#define glGetCompressedTextureImageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMPRESSEDTEXTUREIMAGEEXTPROC);
#define glGetCompressedTextureSubImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOMPRESSEDTEXTURESUBIMAGEPROC);
#define glGetConvolutionFilter(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONFILTERPROC);
#define glGetConvolutionFilterEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONFILTEREXTPROC);
#define glGetConvolutionParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONPARAMETERFVPROC);
#define glGetConvolutionParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONPARAMETERFVEXTPROC);
#define glGetConvolutionParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONPARAMETERIVPROC);
#define glGetConvolutionParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONPARAMETERIVEXTPROC);
#define glGetConvolutionParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCONVOLUTIONPARAMETERXVOESPROC);
#define glGetCoverageModulationTableNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETCOVERAGEMODULATIONTABLENVPROC);
#define glGetDebugMessageLog(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETDEBUGMESSAGELOGPROC);
#define glGetDebugMessageLogAMD(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETDEBUGMESSAGELOGAMDPROC);
#define glGetDebugMessageLogARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETDEBUGMESSAGELOGARBPROC);
#define glGetDetailTexFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETDETAILTEXFUNCSGISPROC);
#define glGetDoubleIndexedvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETDOUBLEINDEXEDVEXTPROC);
#define glGetDoublei_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETDOUBLEI_VPROC);
#define glGetDoublei_vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETDOUBLEI_VEXTPROC);
#define glGetDoublev(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETDOUBLEVPROC);
#define glGetError(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETERRORPROC);
#define glGetFenceivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFENCEIVNVPROC);
#define glGetFinalCombinerInputParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFINALCOMBINERINPUTPARAMETERFVNVPROC);
#define glGetFinalCombinerInputParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFINALCOMBINERINPUTPARAMETERIVNVPROC);
#define glGetFirstPerfQueryIdINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFIRSTPERFQUERYIDINTELPROC);
#define glGetFixedvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFIXEDVOESPROC);
#define glGetFloatIndexedvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFLOATINDEXEDVEXTPROC);
#define glGetFloati_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFLOATI_VPROC);
#define glGetFloati_vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFLOATI_VEXTPROC);
#define glGetFloatv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFLOATVPROC);
#define glGetFogFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFOGFUNCSGISPROC);
#define glGetFragDataIndex(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGDATAINDEXPROC);
#define glGetFragDataLocation(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGDATALOCATIONPROC);
#define glGetFragDataLocationEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGDATALOCATIONEXTPROC);
#define glGetFragmentLightfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGMENTLIGHTFVSGIXPROC);
#define glGetFragmentLightivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGMENTLIGHTIVSGIXPROC);
#define glGetFragmentMaterialfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGMENTMATERIALFVSGIXPROC);
#define glGetFragmentMaterialivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAGMENTMATERIALIVSGIXPROC);
#define glGetFramebufferAttachmentParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC);
#define glGetFramebufferAttachmentParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVEXTPROC);
#define glGetFramebufferParameterfvAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAMEBUFFERPARAMETERFVAMDPROC);
#define glGetFramebufferParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAMEBUFFERPARAMETERIVPROC);
#define glGetFramebufferParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAMEBUFFERPARAMETERIVEXTPROC);
#define glGetFramebufferParameterivMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETFRAMEBUFFERPARAMETERIVMESAPROC);
#define glGetGraphicsResetStatus(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETGRAPHICSRESETSTATUSPROC);
#define glGetGraphicsResetStatusARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETGRAPHICSRESETSTATUSARBPROC);
#define glGetHandleARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETHANDLEARBPROC);
#define glGetHistogram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMPROC);
#define glGetHistogramEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMEXTPROC);
#define glGetHistogramParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMPARAMETERFVPROC);
#define glGetHistogramParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMPARAMETERFVEXTPROC);
#define glGetHistogramParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMPARAMETERIVPROC);
#define glGetHistogramParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMPARAMETERIVEXTPROC);
#define glGetHistogramParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETHISTOGRAMPARAMETERXVOESPROC);
#define glGetImageHandleARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETIMAGEHANDLEARBPROC);
#define glGetImageHandleNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETIMAGEHANDLENVPROC);
#define glGetImageTransformParameterfvHP(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETIMAGETRANSFORMPARAMETERFVHPPROC);
#define glGetImageTransformParameterivHP(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETIMAGETRANSFORMPARAMETERIVHPPROC);
#define glGetInfoLogARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINFOLOGARBPROC);
#define glGetInstrumentsSGIX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETINSTRUMENTSSGIXPROC);
#define glGetInteger64i_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGER64I_VPROC);
#define glGetInteger64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGER64VPROC);
#define glGetIntegerIndexedvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGERINDEXEDVEXTPROC);
#define glGetIntegeri_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGERI_VPROC);
#define glGetIntegerui64i_vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGERUI64I_VNVPROC);
#define glGetIntegerui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGERUI64VNVPROC);
#define glGetIntegerv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTEGERVPROC);
#define glGetInternalformatSampleivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTERNALFORMATSAMPLEIVNVPROC);
#define glGetInternalformati64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTERNALFORMATI64VPROC);
#define glGetInternalformativ(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINTERNALFORMATIVPROC);
#define glGetInvariantBooleanvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINVARIANTBOOLEANVEXTPROC);
#define glGetInvariantFloatvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINVARIANTFLOATVEXTPROC);
#define glGetInvariantIntegervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETINVARIANTINTEGERVEXTPROC);
#define glGetLightfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLIGHTFVPROC);
#define glGetLightiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLIGHTIVPROC);
#define glGetLightxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLIGHTXOESPROC);
#define glGetListParameterfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLISTPARAMETERFVSGIXPROC);
#define glGetListParameterivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLISTPARAMETERIVSGIXPROC);
#define glGetLocalConstantBooleanvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLOCALCONSTANTBOOLEANVEXTPROC);
#define glGetLocalConstantFloatvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLOCALCONSTANTFLOATVEXTPROC);
#define glGetLocalConstantIntegervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETLOCALCONSTANTINTEGERVEXTPROC);
#define glGetMapAttribParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPATTRIBPARAMETERFVNVPROC);
#define glGetMapAttribParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPATTRIBPARAMETERIVNVPROC);
#define glGetMapControlPointsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPCONTROLPOINTSNVPROC);
#define glGetMapParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPPARAMETERFVNVPROC);
#define glGetMapParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPPARAMETERIVNVPROC);
#define glGetMapdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPDVPROC);
#define glGetMapfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPFVPROC);
#define glGetMapiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPIVPROC);
#define glGetMapxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMAPXVOESPROC);
#define glGetMaterialfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMATERIALFVPROC);
#define glGetMaterialiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMATERIALIVPROC);
#define glGetMaterialxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMATERIALXOESPROC);
#define glGetMemoryObjectDetachedResourcesuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMEMORYOBJECTDETACHEDRESOURCESUIVNVPROC);
#define glGetMemoryObjectParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMEMORYOBJECTPARAMETERIVEXTPROC);
#define glGetMinmax(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMINMAXPROC);
#define glGetMinmaxEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMINMAXEXTPROC);
#define glGetMinmaxParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMINMAXPARAMETERFVPROC);
#define glGetMinmaxParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMINMAXPARAMETERFVEXTPROC);
#define glGetMinmaxParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMINMAXPARAMETERIVPROC);
#define glGetMinmaxParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMINMAXPARAMETERIVEXTPROC);
#define glGetMultiTexEnvfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXENVFVEXTPROC);
#define glGetMultiTexEnvivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXENVIVEXTPROC);
#define glGetMultiTexGendvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXGENDVEXTPROC);
#define glGetMultiTexGenfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXGENFVEXTPROC);
#define glGetMultiTexGenivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXGENIVEXTPROC);
#define glGetMultiTexImageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXIMAGEEXTPROC);
#define glGetMultiTexLevelParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXLEVELPARAMETERFVEXTPROC);
#define glGetMultiTexLevelParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXLEVELPARAMETERIVEXTPROC);
#define glGetMultiTexParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXPARAMETERIIVEXTPROC);
#define glGetMultiTexParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXPARAMETERIUIVEXTPROC);
#define glGetMultiTexParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXPARAMETERFVEXTPROC);
#define glGetMultiTexParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTITEXPARAMETERIVEXTPROC);
#define glGetMultisamplefv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTISAMPLEFVPROC);
#define glGetMultisamplefvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETMULTISAMPLEFVNVPROC);
#define glGetNamedBufferParameteri64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERPARAMETERI64VPROC);
#define glGetNamedBufferParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERPARAMETERIVPROC);
#define glGetNamedBufferParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERPARAMETERIVEXTPROC);
#define glGetNamedBufferParameterui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERPARAMETERUI64VNVPROC);
#define glGetNamedBufferPointerv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERPOINTERVPROC);
#define glGetNamedBufferPointervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERPOINTERVEXTPROC);
#define glGetNamedBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERSUBDATAPROC);
#define glGetNamedBufferSubDataEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDBUFFERSUBDATAEXTPROC);
#define glGetNamedFramebufferAttachmentParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDFRAMEBUFFERATTACHMENTPARAMETERIVPROC);
#define glGetNamedFramebufferAttachmentParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDFRAMEBUFFERATTACHMENTPARAMETERIVEXTPROC);
#define glGetNamedFramebufferParameterfvAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDFRAMEBUFFERPARAMETERFVAMDPROC);
#define glGetNamedFramebufferParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDFRAMEBUFFERPARAMETERIVPROC);
#define glGetNamedFramebufferParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDFRAMEBUFFERPARAMETERIVEXTPROC);
#define glGetNamedProgramLocalParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDPROGRAMLOCALPARAMETERIIVEXTPROC);
#define glGetNamedProgramLocalParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDPROGRAMLOCALPARAMETERIUIVEXTPROC);
#define glGetNamedProgramLocalParameterdvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDPROGRAMLOCALPARAMETERDVEXTPROC);
#define glGetNamedProgramLocalParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDPROGRAMLOCALPARAMETERFVEXTPROC);
#define glGetNamedProgramStringEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDPROGRAMSTRINGEXTPROC);
#define glGetNamedProgramivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDPROGRAMIVEXTPROC);
#define glGetNamedRenderbufferParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDRENDERBUFFERPARAMETERIVPROC);
#define glGetNamedRenderbufferParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDRENDERBUFFERPARAMETERIVEXTPROC);
#define glGetNamedStringARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDSTRINGARBPROC);
#define glGetNamedStringivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNAMEDSTRINGIVARBPROC);
#define glGetNextPerfQueryIdINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNEXTPERFQUERYIDINTELPROC);
#define glGetObjectBufferfvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTBUFFERFVATIPROC);
#define glGetObjectBufferivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTBUFFERIVATIPROC);
#define glGetObjectLabel(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTLABELPROC);
#define glGetObjectLabelEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTLABELEXTPROC);
#define glGetObjectParameterfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTPARAMETERFVARBPROC);
#define glGetObjectParameterivAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTPARAMETERIVAPPLEPROC);
#define glGetObjectParameterivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTPARAMETERIVARBPROC);
#define glGetObjectPtrLabel(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOBJECTPTRLABELPROC);
#define glGetOcclusionQueryivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOCCLUSIONQUERYIVNVPROC);
#define glGetOcclusionQueryuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETOCCLUSIONQUERYUIVNVPROC);
#define glGetPathColorGenfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHCOLORGENFVNVPROC);
#define glGetPathColorGenivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHCOLORGENIVNVPROC);
#define glGetPathCommandsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHCOMMANDSNVPROC);
#define glGetPathCoordsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHCOORDSNVPROC);
#define glGetPathDashArrayNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHDASHARRAYNVPROC);
#define glGetPathLengthNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHLENGTHNVPROC);
#define glGetPathMetricRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHMETRICRANGENVPROC);
#define glGetPathMetricsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHMETRICSNVPROC);
#define glGetPathParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHPARAMETERFVNVPROC);
#define glGetPathParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHPARAMETERIVNVPROC);
#define glGetPathSpacingNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHSPACINGNVPROC);
#define glGetPathTexGenfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHTEXGENFVNVPROC);
#define glGetPathTexGenivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPATHTEXGENIVNVPROC);
#define glGetPerfCounterInfoINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFCOUNTERINFOINTELPROC);
#define glGetPerfMonitorCounterDataAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFMONITORCOUNTERDATAAMDPROC);
#define glGetPerfMonitorCounterInfoAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFMONITORCOUNTERINFOAMDPROC);
#define glGetPerfMonitorCounterStringAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFMONITORCOUNTERSTRINGAMDPROC);
#define glGetPerfMonitorCountersAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFMONITORCOUNTERSAMDPROC);
#define glGetPerfMonitorGroupStringAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFMONITORGROUPSTRINGAMDPROC);
#define glGetPerfMonitorGroupsAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFMONITORGROUPSAMDPROC);
#define glGetPerfQueryDataINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFQUERYDATAINTELPROC);
#define glGetPerfQueryIdByNameINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFQUERYIDBYNAMEINTELPROC);
#define glGetPerfQueryInfoINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPERFQUERYINFOINTELPROC);
#define glGetPixelMapfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELMAPFVPROC);
#define glGetPixelMapuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELMAPUIVPROC);
#define glGetPixelMapusv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELMAPUSVPROC);
#define glGetPixelMapxv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELMAPXVPROC);
#define glGetPixelTexGenParameterfvSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELTEXGENPARAMETERFVSGISPROC);
#define glGetPixelTexGenParameterivSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELTEXGENPARAMETERIVSGISPROC);
#define glGetPixelTransformParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELTRANSFORMPARAMETERFVEXTPROC);
#define glGetPixelTransformParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPIXELTRANSFORMPARAMETERIVEXTPROC);
#define glGetPointerIndexedvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPOINTERINDEXEDVEXTPROC);
#define glGetPointeri_vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPOINTERI_VEXTPROC);
#define glGetPointerv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPOINTERVPROC);
#define glGetPointervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPOINTERVEXTPROC);
#define glGetPolygonStipple(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPOLYGONSTIPPLEPROC);
#define glGetProgramBinary(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMBINARYPROC);
#define glGetProgramEnvParameterIivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMENVPARAMETERIIVNVPROC);
#define glGetProgramEnvParameterIuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMENVPARAMETERIUIVNVPROC);
#define glGetProgramEnvParameterdvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMENVPARAMETERDVARBPROC);
#define glGetProgramEnvParameterfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMENVPARAMETERFVARBPROC);
#define glGetProgramInfoLog(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMINFOLOGPROC);
#define glGetProgramInterfaceiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMINTERFACEIVPROC);
#define glGetProgramLocalParameterIivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMLOCALPARAMETERIIVNVPROC);
#define glGetProgramLocalParameterIuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMLOCALPARAMETERIUIVNVPROC);
#define glGetProgramLocalParameterdvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMLOCALPARAMETERDVARBPROC);
#define glGetProgramLocalParameterfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMLOCALPARAMETERFVARBPROC);
#define glGetProgramNamedParameterdvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMNAMEDPARAMETERDVNVPROC);
#define glGetProgramNamedParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMNAMEDPARAMETERFVNVPROC);
#define glGetProgramParameterdvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMPARAMETERDVNVPROC);
#define glGetProgramParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMPARAMETERFVNVPROC);
#define glGetProgramPipelineInfoLog(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMPIPELINEINFOLOGPROC);
#define glGetProgramPipelineiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMPIPELINEIVPROC);
#define glGetProgramResourceIndex(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMRESOURCEINDEXPROC);
#define glGetProgramResourceLocation(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMRESOURCELOCATIONPROC);
#define glGetProgramResourceLocationIndex(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMRESOURCELOCATIONINDEXPROC);
#define glGetProgramResourceName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMRESOURCENAMEPROC);
#define glGetProgramResourcefvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMRESOURCEFVNVPROC);
#define glGetProgramResourceiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMRESOURCEIVPROC);
#define glGetProgramStageiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMSTAGEIVPROC);
#define glGetProgramStringARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMSTRINGARBPROC);
#define glGetProgramStringNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMSTRINGNVPROC);
#define glGetProgramSubroutineParameteruivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMSUBROUTINEPARAMETERUIVNVPROC);
#define glGetProgramiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMIVPROC);
#define glGetProgramivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMIVARBPROC);
#define glGetProgramivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETPROGRAMIVNVPROC);
#define glGetQueryBufferObjecti64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYBUFFEROBJECTI64VPROC);
#define glGetQueryBufferObjectiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYBUFFEROBJECTIVPROC);
#define glGetQueryBufferObjectui64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYBUFFEROBJECTUI64VPROC);
#define glGetQueryBufferObjectuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYBUFFEROBJECTUIVPROC);
#define glGetQueryIndexediv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYINDEXEDIVPROC);
#define glGetQueryObjecti64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTI64VPROC);
#define glGetQueryObjecti64vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTI64VEXTPROC);
#define glGetQueryObjectiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTIVPROC);
#define glGetQueryObjectivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTIVARBPROC);
#define glGetQueryObjectui64v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTUI64VPROC);
#define glGetQueryObjectui64vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTUI64VEXTPROC);
#define glGetQueryObjectuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTUIVPROC);
#define glGetQueryObjectuivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYOBJECTUIVARBPROC);
#define glGetQueryiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYIVPROC);
#define glGetQueryivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETQUERYIVARBPROC);
#define glGetRenderbufferParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETRENDERBUFFERPARAMETERIVPROC);
#define glGetRenderbufferParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETRENDERBUFFERPARAMETERIVEXTPROC);
#define glGetSamplerParameterIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSAMPLERPARAMETERIIVPROC);
#define glGetSamplerParameterIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSAMPLERPARAMETERIUIVPROC);
#define glGetSamplerParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSAMPLERPARAMETERFVPROC);
#define glGetSamplerParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSAMPLERPARAMETERIVPROC);
#define glGetSemaphoreParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSEMAPHOREPARAMETERIVNVPROC);
#define glGetSemaphoreParameterui64vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSEMAPHOREPARAMETERUI64VEXTPROC);
#define glGetSeparableFilter(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSEPARABLEFILTERPROC);
#define glGetSeparableFilterEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSEPARABLEFILTEREXTPROC);
#define glGetShaderInfoLog(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADERINFOLOGPROC);
#define glGetShaderPrecisionFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADERPRECISIONFORMATPROC);
#define glGetShaderSource(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADERSOURCEPROC);
#define glGetShaderSourceARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADERSOURCEARBPROC);
#define glGetShaderiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADERIVPROC);
#define glGetShadingRateImagePaletteNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADINGRATEIMAGEPALETTENVPROC);
#define glGetShadingRateSampleLocationivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHADINGRATESAMPLELOCATIONIVNVPROC);
#define glGetSharpenTexFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSHARPENTEXFUNCSGISPROC);
#define glGetStageIndexNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETSTAGEINDEXNVPROC);
#define glGetString(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETSTRINGPROC);
#define glGetStringi(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETSTRINGIPROC);
#define glGetSubroutineIndex(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETSUBROUTINEINDEXPROC);
#define glGetSubroutineUniformLocation(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETSUBROUTINEUNIFORMLOCATIONPROC);
#define glGetSynciv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETSYNCIVPROC);
#define glGetTexBumpParameterfvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXBUMPPARAMETERFVATIPROC);
#define glGetTexBumpParameterivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXBUMPPARAMETERIVATIPROC);
#define glGetTexEnvfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXENVFVPROC);
#define glGetTexEnviv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXENVIVPROC);
#define glGetTexEnvxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXENVXVOESPROC);
#define glGetTexFilterFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXFILTERFUNCSGISPROC);
#define glGetTexGendv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXGENDVPROC);
#define glGetTexGenfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXGENFVPROC);
#define glGetTexGeniv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXGENIVPROC);
#define glGetTexGenxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXGENXVOESPROC);
#define glGetTexImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXIMAGEPROC);
#define glGetTexLevelParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXLEVELPARAMETERFVPROC);
#define glGetTexLevelParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXLEVELPARAMETERIVPROC);
#define glGetTexLevelParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXLEVELPARAMETERXVOESPROC);
#define glGetTexParameterIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERIIVPROC);
#define glGetTexParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERIIVEXTPROC);
#define glGetTexParameterIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERIUIVPROC);
#define glGetTexParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERIUIVEXTPROC);
#define glGetTexParameterPointervAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERPOINTERVAPPLEPROC);
#define glGetTexParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERFVPROC);
#define glGetTexParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERIVPROC);
#define glGetTexParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXPARAMETERXVOESPROC);
#define glGetTextureHandleARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREHANDLEARBPROC);
#define glGetTextureHandleNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREHANDLENVPROC);
#define glGetTextureImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREIMAGEPROC);
#define glGetTextureImageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREIMAGEEXTPROC);
#define glGetTextureLevelParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURELEVELPARAMETERFVPROC);
#define glGetTextureLevelParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURELEVELPARAMETERFVEXTPROC);
#define glGetTextureLevelParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURELEVELPARAMETERIVPROC);
#define glGetTextureLevelParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURELEVELPARAMETERIVEXTPROC);
#define glGetTextureParameterIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERIIVPROC);
#define glGetTextureParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERIIVEXTPROC);
#define glGetTextureParameterIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERIUIVPROC);
#define glGetTextureParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERIUIVEXTPROC);
#define glGetTextureParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERFVPROC);
#define glGetTextureParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERFVEXTPROC);
#define glGetTextureParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERIVPROC);
#define glGetTextureParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTUREPARAMETERIVEXTPROC);
#define glGetTextureSamplerHandleARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURESAMPLERHANDLEARBPROC);
#define glGetTextureSamplerHandleNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURESAMPLERHANDLENVPROC);
#define glGetTextureSubImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTEXTURESUBIMAGEPROC);
#define glGetTrackMatrixivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRACKMATRIXIVNVPROC);
#define glGetTransformFeedbackVarying(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRANSFORMFEEDBACKVARYINGPROC);
#define glGetTransformFeedbackVaryingEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRANSFORMFEEDBACKVARYINGEXTPROC);
#define glGetTransformFeedbackVaryingNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRANSFORMFEEDBACKVARYINGNVPROC);
#define glGetTransformFeedbacki64_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRANSFORMFEEDBACKI64_VPROC);
#define glGetTransformFeedbacki_v(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRANSFORMFEEDBACKI_VPROC);
#define glGetTransformFeedbackiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETTRANSFORMFEEDBACKIVPROC);
#define glGetUniformBlockIndex(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMBLOCKINDEXPROC);
#define glGetUniformBufferSizeEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMBUFFERSIZEEXTPROC);
#define glGetUniformIndices(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMINDICESPROC);
#define glGetUniformLocation(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMLOCATIONPROC);
#define glGetUniformLocationARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMLOCATIONARBPROC);
#define glGetUniformOffsetEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMOFFSETEXTPROC);
#define glGetUniformSubroutineuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMSUBROUTINEUIVPROC);
#define glGetUniformdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMDVPROC);
#define glGetUniformfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMFVPROC);
#define glGetUniformfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMFVARBPROC);
#define glGetUniformi64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMI64VARBPROC);
#define glGetUniformi64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMI64VNVPROC);
#define glGetUniformiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMIVPROC);
#define glGetUniformivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMIVARBPROC);
#define glGetUniformui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMUI64VARBPROC);
#define glGetUniformui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMUI64VNVPROC);
#define glGetUniformuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMUIVPROC);
#define glGetUniformuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNIFORMUIVEXTPROC);
#define glGetUnsignedBytei_vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNSIGNEDBYTEI_VEXTPROC);
#define glGetUnsignedBytevEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETUNSIGNEDBYTEVEXTPROC);
#define glGetVariantArrayObjectfvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVARIANTARRAYOBJECTFVATIPROC);
#define glGetVariantArrayObjectivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVARIANTARRAYOBJECTIVATIPROC);
#define glGetVariantBooleanvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVARIANTBOOLEANVEXTPROC);
#define glGetVariantFloatvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVARIANTFLOATVEXTPROC);
#define glGetVariantIntegervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVARIANTINTEGERVEXTPROC);
#define glGetVariantPointervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVARIANTPOINTERVEXTPROC);
#define glGetVaryingLocationNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETVARYINGLOCATIONNVPROC);
#define glGetVertexArrayIndexed64iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYINDEXED64IVPROC);
#define glGetVertexArrayIndexediv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYINDEXEDIVPROC);
#define glGetVertexArrayIntegeri_vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYINTEGERI_VEXTPROC);
#define glGetVertexArrayIntegervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYINTEGERVEXTPROC);
#define glGetVertexArrayPointeri_vEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYPOINTERI_VEXTPROC);
#define glGetVertexArrayPointervEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYPOINTERVEXTPROC);
#define glGetVertexArrayiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXARRAYIVPROC);
#define glGetVertexAttribArrayObjectfvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBARRAYOBJECTFVATIPROC);
#define glGetVertexAttribArrayObjectivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBARRAYOBJECTIVATIPROC);
#define glGetVertexAttribIiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIIVPROC);
#define glGetVertexAttribIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIIVEXTPROC);
#define glGetVertexAttribIuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIUIVPROC);
#define glGetVertexAttribIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIUIVEXTPROC);
#define glGetVertexAttribLdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBLDVPROC);
#define glGetVertexAttribLdvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBLDVEXTPROC);
#define glGetVertexAttribLi64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBLI64VNVPROC);
#define glGetVertexAttribLui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBLUI64VARBPROC);
#define glGetVertexAttribLui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBLUI64VNVPROC);
#define glGetVertexAttribPointerv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBPOINTERVPROC);
#define glGetVertexAttribPointervARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBPOINTERVARBPROC);
#define glGetVertexAttribPointervNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBPOINTERVNVPROC);
#define glGetVertexAttribdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBDVPROC);
#define glGetVertexAttribdvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBDVARBPROC);
#define glGetVertexAttribdvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBDVNVPROC);
#define glGetVertexAttribfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBFVPROC);
#define glGetVertexAttribfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBFVARBPROC);
#define glGetVertexAttribfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBFVNVPROC);
#define glGetVertexAttribiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIVPROC);
#define glGetVertexAttribivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIVARBPROC);
#define glGetVertexAttribivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVERTEXATTRIBIVNVPROC);
#define glGetVideoCaptureStreamdvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOCAPTURESTREAMDVNVPROC);
#define glGetVideoCaptureStreamfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOCAPTURESTREAMFVNVPROC);
#define glGetVideoCaptureStreamivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOCAPTURESTREAMIVNVPROC);
#define glGetVideoCaptureivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOCAPTUREIVNVPROC);
#define glGetVideoi64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOI64VNVPROC);
#define glGetVideoivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOIVNVPROC);
#define glGetVideoui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOUI64VNVPROC);
#define glGetVideouivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETVIDEOUIVNVPROC);
#define glGetVkProcAddrNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLGETVKPROCADDRNVPROC);
#define glGetnColorTable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNCOLORTABLEPROC);
#define glGetnColorTableARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNCOLORTABLEARBPROC);
#define glGetnCompressedTexImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNCOMPRESSEDTEXIMAGEPROC);
#define glGetnCompressedTexImageARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNCOMPRESSEDTEXIMAGEARBPROC);
#define glGetnConvolutionFilter(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNCONVOLUTIONFILTERPROC);
#define glGetnConvolutionFilterARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNCONVOLUTIONFILTERARBPROC);
#define glGetnHistogram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNHISTOGRAMPROC);
#define glGetnHistogramARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNHISTOGRAMARBPROC);
#define glGetnMapdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMAPDVPROC);
#define glGetnMapdvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMAPDVARBPROC);
#define glGetnMapfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMAPFVPROC);
#define glGetnMapfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMAPFVARBPROC);
#define glGetnMapiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMAPIVPROC);
#define glGetnMapivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMAPIVARBPROC);
#define glGetnMinmax(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMINMAXPROC);
#define glGetnMinmaxARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNMINMAXARBPROC);
#define glGetnPixelMapfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPIXELMAPFVPROC);
#define glGetnPixelMapfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPIXELMAPFVARBPROC);
#define glGetnPixelMapuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPIXELMAPUIVPROC);
#define glGetnPixelMapuivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPIXELMAPUIVARBPROC);
#define glGetnPixelMapusv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPIXELMAPUSVPROC);
#define glGetnPixelMapusvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPIXELMAPUSVARBPROC);
#define glGetnPolygonStipple(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPOLYGONSTIPPLEPROC);
#define glGetnPolygonStippleARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNPOLYGONSTIPPLEARBPROC);
#define glGetnSeparableFilter(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNSEPARABLEFILTERPROC);
#define glGetnSeparableFilterARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNSEPARABLEFILTERARBPROC);
#define glGetnTexImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNTEXIMAGEPROC);
#define glGetnTexImageARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNTEXIMAGEARBPROC);
#define glGetnUniformdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMDVPROC);
#define glGetnUniformdvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMDVARBPROC);
#define glGetnUniformfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMFVPROC);
#define glGetnUniformfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMFVARBPROC);
#define glGetnUniformi64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMI64VARBPROC);
#define glGetnUniformiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMIVPROC);
#define glGetnUniformivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMIVARBPROC);
#define glGetnUniformui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMUI64VARBPROC);
#define glGetnUniformuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMUIVPROC);
#define glGetnUniformuivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGETNUNIFORMUIVARBPROC);
#define glGlobalAlphaFactorbSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORBSUNPROC);
#define glGlobalAlphaFactordSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORDSUNPROC);
#define glGlobalAlphaFactorfSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORFSUNPROC);
#define glGlobalAlphaFactoriSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORISUNPROC);
#define glGlobalAlphaFactorsSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORSSUNPROC);
#define glGlobalAlphaFactorubSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORUBSUNPROC);
#define glGlobalAlphaFactoruiSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORUISUNPROC);
#define glGlobalAlphaFactorusSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLGLOBALALPHAFACTORUSSUNPROC);
#define glHint(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLHINTPROC);
#define glHintPGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLHINTPGIPROC);
#define glHistogram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLHISTOGRAMPROC);
#define glHistogramEXT(...) ((void)0)
