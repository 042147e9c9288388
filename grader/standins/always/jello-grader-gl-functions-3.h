/* jello-grader-gl-functions-3.h: the GL, GLU and GLUT functions of the grader's GL stand-in
   (jello-grader-gl.h), a part of at most 60000 bytes: each file built into the
   grader stays a string under 64 kB. Made by scripts/make-gl-standins. */
typedef JELLO_GRADER_PROC(PFNGLHISTOGRAMEXTPROC);
#define glIglooInterfaceSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIGLOOINTERFACESGIXPROC);
#define glImageTransformParameterfHP(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMAGETRANSFORMPARAMETERFHPPROC);
#define glImageTransformParameterfvHP(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMAGETRANSFORMPARAMETERFVHPPROC);
#define glImageTransformParameteriHP(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMAGETRANSFORMPARAMETERIHPPROC);
#define glImageTransformParameterivHP(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMAGETRANSFORMPARAMETERIVHPPROC);
#define glImportMemoryFdEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTMEMORYFDEXTPROC);
#define glImportMemoryWin32HandleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTMEMORYWIN32HANDLEEXTPROC);
#define glImportMemoryWin32NameEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTMEMORYWIN32NAMEEXTPROC);
#define glImportSemaphoreFdEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTSEMAPHOREFDEXTPROC);
#define glImportSemaphoreWin32HandleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTSEMAPHOREWIN32HANDLEEXTPROC);
#define glImportSemaphoreWin32NameEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTSEMAPHOREWIN32NAMEEXTPROC);
#define glImportSyncEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLIMPORTSYNCEXTPROC);
#define glIndexFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXFORMATNVPROC);
#define glIndexFuncEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXFUNCEXTPROC);
#define glIndexMask(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXMASKPROC);
#define glIndexMaterialEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXMATERIALEXTPROC);
#define glIndexPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXPOINTERPROC);
#define glIndexPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXPOINTEREXTPROC);
#define glIndexPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXPOINTERLISTIBMPROC);
#define glIndexd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXDPROC);
#define glIndexdv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXDVPROC);
#define glIndexf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXFPROC);
#define glIndexfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXFVPROC);
#define glIndexi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXIPROC);
#define glIndexiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXIVPROC);
#define glIndexs(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXSPROC);
#define glIndexsv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXSVPROC);
#define glIndexub(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXUBPROC);
#define glIndexubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXUBVPROC);
#define glIndexxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXXOESPROC);
#define glIndexxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINDEXXVOESPROC);
#define glInitNames(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINITNAMESPROC);
#define glInsertComponentEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINSERTCOMPONENTEXTPROC);
#define glInsertEventMarkerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINSERTEVENTMARKEREXTPROC);
#define glInstrumentsBufferSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINSTRUMENTSBUFFERSGIXPROC);
#define glInterleavedArrays(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINTERLEAVEDARRAYSPROC);
#define glInterpolatePathsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINTERPOLATEPATHSNVPROC);
#define glInvalidateBufferData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATEBUFFERDATAPROC);
#define glInvalidateBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATEBUFFERSUBDATAPROC);
#define glInvalidateFramebuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATEFRAMEBUFFERPROC);
#define glInvalidateNamedFramebufferData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATENAMEDFRAMEBUFFERDATAPROC);
#define glInvalidateNamedFramebufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATENAMEDFRAMEBUFFERSUBDATAPROC);
#define glInvalidateSubFramebuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATESUBFRAMEBUFFERPROC);
#define glInvalidateTexImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATETEXIMAGEPROC);
#define glInvalidateTexSubImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLINVALIDATETEXSUBIMAGEPROC);
#define glIsAsyncMarkerSGIX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISASYNCMARKERSGIXPROC);
#define glIsBuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISBUFFERPROC);
#define glIsBufferARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISBUFFERARBPROC);
#define glIsBufferResidentNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISBUFFERRESIDENTNVPROC);
#define glIsCommandListNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISCOMMANDLISTNVPROC);
#define glIsEnabled(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISENABLEDPROC);
#define glIsEnabledIndexedEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISENABLEDINDEXEDEXTPROC);
#define glIsEnabledi(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISENABLEDIPROC);
#define glIsFenceAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISFENCEAPPLEPROC);
#define glIsFenceNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISFENCENVPROC);
#define glIsFramebuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISFRAMEBUFFERPROC);
#define glIsFramebufferEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISFRAMEBUFFEREXTPROC);
#define glIsImageHandleResidentARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISIMAGEHANDLERESIDENTARBPROC);
#define glIsImageHandleResidentNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISIMAGEHANDLERESIDENTNVPROC);
#define glIsList(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISLISTPROC);
#define glIsMemoryObjectEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISMEMORYOBJECTEXTPROC);
#define glIsNameAMD(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISNAMEAMDPROC);
#define glIsNamedBufferResidentNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISNAMEDBUFFERRESIDENTNVPROC);
#define glIsNamedStringARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISNAMEDSTRINGARBPROC);
#define glIsObjectBufferATI(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISOBJECTBUFFERATIPROC);
#define glIsOcclusionQueryNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISOCCLUSIONQUERYNVPROC);
#define glIsPathNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPATHNVPROC);
#define glIsPointInFillPathNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPOINTINFILLPATHNVPROC);
#define glIsPointInStrokePathNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPOINTINSTROKEPATHNVPROC);
#define glIsProgram(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPROGRAMPROC);
#define glIsProgramARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPROGRAMARBPROC);
#define glIsProgramNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPROGRAMNVPROC);
#define glIsProgramPipeline(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISPROGRAMPIPELINEPROC);
#define glIsQuery(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISQUERYPROC);
#define glIsQueryARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISQUERYARBPROC);
#define glIsRenderbuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISRENDERBUFFERPROC);
#define glIsRenderbufferEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISRENDERBUFFEREXTPROC);
#define glIsSampler(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISSAMPLERPROC);
#define glIsSemaphoreEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISSEMAPHOREEXTPROC);
#define glIsShader(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISSHADERPROC);
#define glIsStateNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISSTATENVPROC);
#define glIsSync(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISSYNCPROC);
#define glIsTexture(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISTEXTUREPROC);
#define glIsTextureEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISTEXTUREEXTPROC);
#define glIsTextureHandleResidentARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISTEXTUREHANDLERESIDENTARBPROC);
#define glIsTextureHandleResidentNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISTEXTUREHANDLERESIDENTNVPROC);
#define glIsTransformFeedback(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISTRANSFORMFEEDBACKPROC);
#define glIsTransformFeedbackNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISTRANSFORMFEEDBACKNVPROC);
#define glIsVariantEnabledEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISVARIANTENABLEDEXTPROC);
#define glIsVertexArray(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISVERTEXARRAYPROC);
#define glIsVertexArrayAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISVERTEXARRAYAPPLEPROC);
#define glIsVertexAttribEnabledAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLISVERTEXATTRIBENABLEDAPPLEPROC);
#define glLGPUCopyImageSubDataNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLGPUCOPYIMAGESUBDATANVXPROC);
#define glLGPUInterlockNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLGPUINTERLOCKNVXPROC);
#define glLGPUNamedBufferSubDataNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLGPUNAMEDBUFFERSUBDATANVXPROC);
#define glLabelObjectEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLABELOBJECTEXTPROC);
#define glLightEnviSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTENVISGIXPROC);
#define glLightModelf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTMODELFPROC);
#define glLightModelfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTMODELFVPROC);
#define glLightModeli(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTMODELIPROC);
#define glLightModeliv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTMODELIVPROC);
#define glLightModelxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTMODELXOESPROC);
#define glLightModelxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTMODELXVOESPROC);
#define glLightf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTFPROC);
#define glLightfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTFVPROC);
#define glLighti(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTIPROC);
#define glLightiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTIVPROC);
#define glLightxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTXOESPROC);
#define glLightxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLIGHTXVOESPROC);
#define glLineStipple(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLINESTIPPLEPROC);
#define glLineWidth(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLINEWIDTHPROC);
#define glLineWidthxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLINEWIDTHXOESPROC);
#define glLinkProgram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLINKPROGRAMPROC);
#define glLinkProgramARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLINKPROGRAMARBPROC);
#define glListBase(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLISTBASEPROC);
#define glListDrawCommandsStatesClientNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLISTDRAWCOMMANDSSTATESCLIENTNVPROC);
#define glListParameterfSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLISTPARAMETERFSGIXPROC);
#define glListParameterfvSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLISTPARAMETERFVSGIXPROC);
#define glListParameteriSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLISTPARAMETERISGIXPROC);
#define glListParameterivSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLISTPARAMETERIVSGIXPROC);
#define glLoadIdentity(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADIDENTITYPROC);
#define glLoadIdentityDeformationMapSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADIDENTITYDEFORMATIONMAPSGIXPROC);
#define glLoadMatrixd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADMATRIXDPROC);
#define glLoadMatrixf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADMATRIXFPROC);
#define glLoadMatrixxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADMATRIXXOESPROC);
#define glLoadName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADNAMEPROC);
#define glLoadProgramNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADPROGRAMNVPROC);
#define glLoadTransposeMatrixd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADTRANSPOSEMATRIXDPROC);
#define glLoadTransposeMatrixdARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADTRANSPOSEMATRIXDARBPROC);
#define glLoadTransposeMatrixf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADTRANSPOSEMATRIXFPROC);
#define glLoadTransposeMatrixfARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADTRANSPOSEMATRIXFARBPROC);
#define glLoadTransposeMatrixxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOADTRANSPOSEMATRIXXOESPROC);
#define glLockArraysEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOCKARRAYSEXTPROC);
#define glLogicOp(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLLOGICOPPROC);
#define glMakeBufferNonResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKEBUFFERNONRESIDENTNVPROC);
#define glMakeBufferResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKEBUFFERRESIDENTNVPROC);
#define glMakeImageHandleNonResidentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKEIMAGEHANDLENONRESIDENTARBPROC);
#define glMakeImageHandleNonResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKEIMAGEHANDLENONRESIDENTNVPROC);
#define glMakeImageHandleResidentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKEIMAGEHANDLERESIDENTARBPROC);
#define glMakeImageHandleResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKEIMAGEHANDLERESIDENTNVPROC);
#define glMakeNamedBufferNonResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKENAMEDBUFFERNONRESIDENTNVPROC);
#define glMakeNamedBufferResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKENAMEDBUFFERRESIDENTNVPROC);
#define glMakeTextureHandleNonResidentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKETEXTUREHANDLENONRESIDENTARBPROC);
#define glMakeTextureHandleNonResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKETEXTUREHANDLENONRESIDENTNVPROC);
#define glMakeTextureHandleResidentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKETEXTUREHANDLERESIDENTARBPROC);
#define glMakeTextureHandleResidentNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAKETEXTUREHANDLERESIDENTNVPROC);
#define glMap1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAP1DPROC);
#define glMap1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAP1FPROC);
#define glMap1xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAP1XOESPROC);
#define glMap2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAP2DPROC);
#define glMap2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAP2FPROC);
#define glMap2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAP2XOESPROC);
#define glMapBuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPBUFFERPROC);
#define glMapBufferARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPBUFFERARBPROC);
#define glMapBufferRange(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPBUFFERRANGEPROC);
#define glMapControlPointsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPCONTROLPOINTSNVPROC);
#define glMapGrid1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPGRID1DPROC);
#define glMapGrid1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPGRID1FPROC);
#define glMapGrid1xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPGRID1XOESPROC);
#define glMapGrid2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPGRID2DPROC);
#define glMapGrid2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPGRID2FPROC);
#define glMapGrid2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPGRID2XOESPROC);
#define glMapNamedBuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPNAMEDBUFFERPROC);
#define glMapNamedBufferEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPNAMEDBUFFEREXTPROC);
#define glMapNamedBufferRange(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPNAMEDBUFFERRANGEPROC);
#define glMapNamedBufferRangeEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPNAMEDBUFFERRANGEEXTPROC);
#define glMapObjectBufferATI(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPOBJECTBUFFERATIPROC);
#define glMapParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPPARAMETERFVNVPROC);
#define glMapParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPPARAMETERIVNVPROC);
#define glMapTexture2DINTEL(...) (0)
typedef JELLO_GRADER_PROC(PFNGLMAPTEXTURE2DINTELPROC);
#define glMapVertexAttrib1dAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPVERTEXATTRIB1DAPPLEPROC);
#define glMapVertexAttrib1fAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPVERTEXATTRIB1FAPPLEPROC);
#define glMapVertexAttrib2dAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPVERTEXATTRIB2DAPPLEPROC);
#define glMapVertexAttrib2fAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAPVERTEXATTRIB2FAPPLEPROC);
#define glMaterialf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATERIALFPROC);
#define glMaterialfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATERIALFVPROC);
#define glMateriali(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATERIALIPROC);
#define glMaterialiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATERIALIVPROC);
#define glMaterialxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATERIALXOESPROC);
#define glMaterialxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATERIALXVOESPROC);
#define glMatrixFrustumEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXFRUSTUMEXTPROC);
#define glMatrixIndexPointerARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXINDEXPOINTERARBPROC);
#define glMatrixIndexubvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXINDEXUBVARBPROC);
#define glMatrixIndexuivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXINDEXUIVARBPROC);
#define glMatrixIndexusvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXINDEXUSVARBPROC);
#define glMatrixLoad3x2fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOAD3X2FNVPROC);
#define glMatrixLoad3x3fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOAD3X3FNVPROC);
#define glMatrixLoadIdentityEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOADIDENTITYEXTPROC);
#define glMatrixLoadTranspose3x3fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOADTRANSPOSE3X3FNVPROC);
#define glMatrixLoadTransposedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOADTRANSPOSEDEXTPROC);
#define glMatrixLoadTransposefEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOADTRANSPOSEFEXTPROC);
#define glMatrixLoaddEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOADDEXTPROC);
#define glMatrixLoadfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXLOADFEXTPROC);
#define glMatrixMode(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMODEPROC);
#define glMatrixMult3x2fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULT3X2FNVPROC);
#define glMatrixMult3x3fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULT3X3FNVPROC);
#define glMatrixMultTranspose3x3fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULTTRANSPOSE3X3FNVPROC);
#define glMatrixMultTransposedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULTTRANSPOSEDEXTPROC);
#define glMatrixMultTransposefEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULTTRANSPOSEFEXTPROC);
#define glMatrixMultdEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULTDEXTPROC);
#define glMatrixMultfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXMULTFEXTPROC);
#define glMatrixOrthoEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXORTHOEXTPROC);
#define glMatrixPopEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXPOPEXTPROC);
#define glMatrixPushEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXPUSHEXTPROC);
#define glMatrixRotatedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXROTATEDEXTPROC);
#define glMatrixRotatefEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXROTATEFEXTPROC);
#define glMatrixScaledEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXSCALEDEXTPROC);
#define glMatrixScalefEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXSCALEFEXTPROC);
#define glMatrixTranslatedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXTRANSLATEDEXTPROC);
#define glMatrixTranslatefEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMATRIXTRANSLATEFEXTPROC);
#define glMaxShaderCompilerThreadsARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAXSHADERCOMPILERTHREADSARBPROC);
#define glMaxShaderCompilerThreadsKHR(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMAXSHADERCOMPILERTHREADSKHRPROC);
#define glMemoryBarrier(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMEMORYBARRIERPROC);
#define glMemoryBarrierByRegion(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMEMORYBARRIERBYREGIONPROC);
#define glMemoryBarrierEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMEMORYBARRIEREXTPROC);
#define glMemoryObjectParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMEMORYOBJECTPARAMETERIVEXTPROC);
#define glMinSampleShading(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMINSAMPLESHADINGPROC);
#define glMinSampleShadingARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMINSAMPLESHADINGARBPROC);
#define glMinmax(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMINMAXPROC);
#define glMinmaxEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMINMAXEXTPROC);
#define glMultMatrixd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTMATRIXDPROC);
#define glMultMatrixf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTMATRIXFPROC);
#define glMultMatrixxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTMATRIXXOESPROC);
#define glMultTransposeMatrixd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTTRANSPOSEMATRIXDPROC);
#define glMultTransposeMatrixdARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTTRANSPOSEMATRIXDARBPROC);
#define glMultTransposeMatrixf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTTRANSPOSEMATRIXFPROC);
#define glMultTransposeMatrixfARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTTRANSPOSEMATRIXFARBPROC);
#define glMultTransposeMatrixxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTTRANSPOSEMATRIXXOESPROC);
#define glMultiDrawArrays(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSPROC);
#define glMultiDrawArraysEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSEXTPROC);
#define glMultiDrawArraysIndirect(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSINDIRECTPROC);
#define glMultiDrawArraysIndirectAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSINDIRECTAMDPROC);
#define glMultiDrawArraysIndirectBindlessCountNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSINDIRECTBINDLESSCOUNTNVPROC);
#define glMultiDrawArraysIndirectBindlessNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSINDIRECTBINDLESSNVPROC);
#define glMultiDrawArraysIndirectCount(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSINDIRECTCOUNTPROC);
#define glMultiDrawArraysIndirectCountARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWARRAYSINDIRECTCOUNTARBPROC);
#define glMultiDrawElementArrayAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTARRAYAPPLEPROC);
#define glMultiDrawElements(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSPROC);
#define glMultiDrawElementsBaseVertex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSBASEVERTEXPROC);
#define glMultiDrawElementsEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSEXTPROC);
#define glMultiDrawElementsIndirect(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSINDIRECTPROC);
#define glMultiDrawElementsIndirectAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSINDIRECTAMDPROC);
#define glMultiDrawElementsIndirectBindlessCountNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSINDIRECTBINDLESSCOUNTNVPROC);
#define glMultiDrawElementsIndirectBindlessNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSINDIRECTBINDLESSNVPROC);
#define glMultiDrawElementsIndirectCount(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSINDIRECTCOUNTPROC);
#define glMultiDrawElementsIndirectCountARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWELEMENTSINDIRECTCOUNTARBPROC);
#define glMultiDrawMeshTasksIndirectCountNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWMESHTASKSINDIRECTCOUNTNVPROC);
#define glMultiDrawMeshTasksIndirectNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWMESHTASKSINDIRECTNVPROC);
#define glMultiDrawRangeElementArrayAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIDRAWRANGEELEMENTARRAYAPPLEPROC);
#define glMultiModeDrawArraysIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIMODEDRAWARRAYSIBMPROC);
#define glMultiModeDrawElementsIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTIMODEDRAWELEMENTSIBMPROC);
#define glMultiTexBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXBUFFEREXTPROC);
#define glMultiTexCoord1bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1BOESPROC);
#define glMultiTexCoord1bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1BVOESPROC);
#define glMultiTexCoord1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1DPROC);
#define glMultiTexCoord1dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1DARBPROC);
#define glMultiTexCoord1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1DVPROC);
#define glMultiTexCoord1dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1DVARBPROC);
#define glMultiTexCoord1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1FPROC);
#define glMultiTexCoord1fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1FARBPROC);
#define glMultiTexCoord1fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1FVPROC);
#define glMultiTexCoord1fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1FVARBPROC);
#define glMultiTexCoord1hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1HNVPROC);
#define glMultiTexCoord1hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1HVNVPROC);
#define glMultiTexCoord1i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1IPROC);
#define glMultiTexCoord1iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1IARBPROC);
#define glMultiTexCoord1iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1IVPROC);
#define glMultiTexCoord1ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1IVARBPROC);
#define glMultiTexCoord1s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1SPROC);
#define glMultiTexCoord1sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1SARBPROC);
#define glMultiTexCoord1sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1SVPROC);
#define glMultiTexCoord1svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1SVARBPROC);
#define glMultiTexCoord1xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1XOESPROC);
#define glMultiTexCoord1xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD1XVOESPROC);
#define glMultiTexCoord2bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2BOESPROC);
#define glMultiTexCoord2bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2BVOESPROC);
#define glMultiTexCoord2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2DPROC);
#define glMultiTexCoord2dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2DARBPROC);
#define glMultiTexCoord2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2DVPROC);
#define glMultiTexCoord2dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2DVARBPROC);
#define glMultiTexCoord2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2FPROC);
#define glMultiTexCoord2fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2FARBPROC);
#define glMultiTexCoord2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2FVPROC);
#define glMultiTexCoord2fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2FVARBPROC);
#define glMultiTexCoord2hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2HNVPROC);
#define glMultiTexCoord2hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2HVNVPROC);
#define glMultiTexCoord2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2IPROC);
#define glMultiTexCoord2iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2IARBPROC);
#define glMultiTexCoord2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2IVPROC);
#define glMultiTexCoord2ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2IVARBPROC);
#define glMultiTexCoord2s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2SPROC);
#define glMultiTexCoord2sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2SARBPROC);
#define glMultiTexCoord2sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2SVPROC);
#define glMultiTexCoord2svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2SVARBPROC);
#define glMultiTexCoord2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2XOESPROC);
#define glMultiTexCoord2xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD2XVOESPROC);
#define glMultiTexCoord3bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3BOESPROC);
#define glMultiTexCoord3bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3BVOESPROC);
#define glMultiTexCoord3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3DPROC);
#define glMultiTexCoord3dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3DARBPROC);
#define glMultiTexCoord3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3DVPROC);
#define glMultiTexCoord3dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3DVARBPROC);
#define glMultiTexCoord3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3FPROC);
#define glMultiTexCoord3fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3FARBPROC);
#define glMultiTexCoord3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3FVPROC);
#define glMultiTexCoord3fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3FVARBPROC);
#define glMultiTexCoord3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3HNVPROC);
#define glMultiTexCoord3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3HVNVPROC);
#define glMultiTexCoord3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3IPROC);
#define glMultiTexCoord3iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3IARBPROC);
#define glMultiTexCoord3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3IVPROC);
#define glMultiTexCoord3ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3IVARBPROC);
#define glMultiTexCoord3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3SPROC);
#define glMultiTexCoord3sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3SARBPROC);
#define glMultiTexCoord3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3SVPROC);
#define glMultiTexCoord3svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3SVARBPROC);
#define glMultiTexCoord3xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3XOESPROC);
#define glMultiTexCoord3xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD3XVOESPROC);
#define glMultiTexCoord4bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4BOESPROC);
#define glMultiTexCoord4bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4BVOESPROC);
#define glMultiTexCoord4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4DPROC);
#define glMultiTexCoord4dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4DARBPROC);
#define glMultiTexCoord4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4DVPROC);
#define glMultiTexCoord4dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4DVARBPROC);
#define glMultiTexCoord4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4FPROC);
#define glMultiTexCoord4fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4FARBPROC);
#define glMultiTexCoord4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4FVPROC);
#define glMultiTexCoord4fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4FVARBPROC);
#define glMultiTexCoord4hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4HNVPROC);
#define glMultiTexCoord4hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4HVNVPROC);
#define glMultiTexCoord4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4IPROC);
#define glMultiTexCoord4iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4IARBPROC);
#define glMultiTexCoord4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4IVPROC);
#define glMultiTexCoord4ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4IVARBPROC);
#define glMultiTexCoord4s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4SPROC);
#define glMultiTexCoord4sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4SARBPROC);
#define glMultiTexCoord4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4SVPROC);
#define glMultiTexCoord4svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4SVARBPROC);
#define glMultiTexCoord4xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4XOESPROC);
#define glMultiTexCoord4xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORD4XVOESPROC);
#define glMultiTexCoordP1ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP1UIPROC);
#define glMultiTexCoordP1uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP1UIVPROC);
#define glMultiTexCoordP2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP2UIPROC);
#define glMultiTexCoordP2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP2UIVPROC);
#define glMultiTexCoordP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP3UIPROC);
#define glMultiTexCoordP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP3UIVPROC);
#define glMultiTexCoordP4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP4UIPROC);
#define glMultiTexCoordP4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDP4UIVPROC);
#define glMultiTexCoordPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXCOORDPOINTEREXTPROC);
#define glMultiTexEnvfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXENVFEXTPROC);
#define glMultiTexEnvfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXENVFVEXTPROC);
#define glMultiTexEnviEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXENVIEXTPROC);
#define glMultiTexEnvivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXENVIVEXTPROC);
#define glMultiTexGendEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXGENDEXTPROC);
#define glMultiTexGendvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXGENDVEXTPROC);
#define glMultiTexGenfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXGENFEXTPROC);
#define glMultiTexGenfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXGENFVEXTPROC);
#define glMultiTexGeniEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXGENIEXTPROC);
#define glMultiTexGenivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXGENIVEXTPROC);
#define glMultiTexImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXIMAGE1DEXTPROC);
#define glMultiTexImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXIMAGE2DEXTPROC);
#define glMultiTexImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXIMAGE3DEXTPROC);
#define glMultiTexParameterIivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXPARAMETERIIVEXTPROC);
#define glMultiTexParameterIuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXPARAMETERIUIVEXTPROC);
#define glMultiTexParameterfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXPARAMETERFEXTPROC);
#define glMultiTexParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXPARAMETERFVEXTPROC);
#define glMultiTexParameteriEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXPARAMETERIEXTPROC);
#define glMultiTexParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXPARAMETERIVEXTPROC);
#define glMultiTexRenderbufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXRENDERBUFFEREXTPROC);
#define glMultiTexSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXSUBIMAGE1DEXTPROC);
#define glMultiTexSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXSUBIMAGE2DEXTPROC);
#define glMultiTexSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTITEXSUBIMAGE3DEXTPROC);
#define glMulticastBarrierNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTBARRIERNVPROC);
#define glMulticastBlitFramebufferNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTBLITFRAMEBUFFERNVPROC);
#define glMulticastBufferSubDataNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTBUFFERSUBDATANVPROC);
#define glMulticastCopyBufferSubDataNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTCOPYBUFFERSUBDATANVPROC);
#define glMulticastCopyImageSubDataNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTCOPYIMAGESUBDATANVPROC);
#define glMulticastFramebufferSampleLocationsfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTFRAMEBUFFERSAMPLELOCATIONSFVNVPROC);
#define glMulticastGetQueryObjecti64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTGETQUERYOBJECTI64VNVPROC);
#define glMulticastGetQueryObjectivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTGETQUERYOBJECTIVNVPROC);
#define glMulticastGetQueryObjectui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTGETQUERYOBJECTUI64VNVPROC);
#define glMulticastGetQueryObjectuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTGETQUERYOBJECTUIVNVPROC);
#define glMulticastScissorArrayvNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTSCISSORARRAYVNVXPROC);
#define glMulticastViewportArrayvNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTVIEWPORTARRAYVNVXPROC);
#define glMulticastViewportPositionWScaleNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTVIEWPORTPOSITIONWSCALENVXPROC);
#define glMulticastWaitSyncNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLMULTICASTWAITSYNCNVPROC);
#define glNamedBufferAttachMemoryNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERATTACHMEMORYNVPROC);
#define glNamedBufferData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERDATAPROC);
#define glNamedBufferDataEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERDATAEXTPROC);
#define glNamedBufferPageCommitmentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERPAGECOMMITMENTARBPROC);
#define glNamedBufferPageCommitmentEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERPAGECOMMITMENTEXTPROC);
#define glNamedBufferPageCommitmentMemNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERPAGECOMMITMENTMEMNVPROC);
#define glNamedBufferStorage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERSTORAGEPROC);
#define glNamedBufferStorageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERSTORAGEEXTPROC);
#define glNamedBufferStorageExternalEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERSTORAGEEXTERNALEXTPROC);
#define glNamedBufferStorageMemEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERSTORAGEMEMEXTPROC);
#define glNamedBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERSUBDATAPROC);
#define glNamedBufferSubDataEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDBUFFERSUBDATAEXTPROC);
#define glNamedCopyBufferSubDataEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDCOPYBUFFERSUBDATAEXTPROC);
#define glNamedFramebufferDrawBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERPROC);
#define glNamedFramebufferDrawBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC);
#define glNamedFramebufferParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERPARAMETERIPROC);
#define glNamedFramebufferParameteriEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERPARAMETERIEXTPROC);
#define glNamedFramebufferReadBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERREADBUFFERPROC);
#define glNamedFramebufferRenderbuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC);
#define glNamedFramebufferRenderbufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERRENDERBUFFEREXTPROC);
#define glNamedFramebufferSampleLocationsfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERSAMPLELOCATIONSFVARBPROC);
#define glNamedFramebufferSampleLocationsfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERSAMPLELOCATIONSFVNVPROC);
#define glNamedFramebufferSamplePositionsfvAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERSAMPLEPOSITIONSFVAMDPROC);
#define glNamedFramebufferTexture(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC);
#define glNamedFramebufferTexture1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTURE1DEXTPROC);
#define glNamedFramebufferTexture2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTURE2DEXTPROC);
#define glNamedFramebufferTexture3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTURE3DEXTPROC);
#define glNamedFramebufferTextureEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTUREEXTPROC);
#define glNamedFramebufferTextureFaceEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTUREFACEEXTPROC);
#define glNamedFramebufferTextureLayer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTURELAYERPROC);
#define glNamedFramebufferTextureLayerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDFRAMEBUFFERTEXTURELAYEREXTPROC);
#define glNamedProgramLocalParameter4dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETER4DEXTPROC);
#define glNamedProgramLocalParameter4dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETER4DVEXTPROC);
#define glNamedProgramLocalParameter4fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETER4FEXTPROC);
#define glNamedProgramLocalParameter4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETER4FVEXTPROC);
#define glNamedProgramLocalParameterI4iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERI4IEXTPROC);
#define glNamedProgramLocalParameterI4ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERI4IVEXTPROC);
#define glNamedProgramLocalParameterI4uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERI4UIEXTPROC);
#define glNamedProgramLocalParameterI4uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERI4UIVEXTPROC);
#define glNamedProgramLocalParameters4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERS4FVEXTPROC);
#define glNamedProgramLocalParametersI4ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERSI4IVEXTPROC);
#define glNamedProgramLocalParametersI4uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMLOCALPARAMETERSI4UIVEXTPROC);
#define glNamedProgramStringEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDPROGRAMSTRINGEXTPROC);
#define glNamedRenderbufferStorage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDRENDERBUFFERSTORAGEPROC);
#define glNamedRenderbufferStorageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDRENDERBUFFERSTORAGEEXTPROC);
#define glNamedRenderbufferStorageMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLEPROC);
#define glNamedRenderbufferStorageMultisampleAdvancedAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLEADVANCEDAMDPROC);
#define glNamedRenderbufferStorageMultisampleCoverageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLECOVERAGEEXTPROC);
#define glNamedRenderbufferStorageMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLEEXTPROC);
#define glNamedStringARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNAMEDSTRINGARBPROC);
#define glNewList(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNEWLISTPROC);
#define glNewObjectBufferATI(...) (0)
typedef JELLO_GRADER_PROC(PFNGLNEWOBJECTBUFFERATIPROC);
#define glNormal3b(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3BPROC);
#define glNormal3bv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3BVPROC);
#define glNormal3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3DPROC);
#define glNormal3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3DVPROC);
#define glNormal3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3FPROC);
#define glNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3FVERTEX3FSUNPROC);
#define glNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3FVERTEX3FVSUNPROC);
#define glNormal3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3FVPROC);
#define glNormal3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3HNVPROC);
#define glNormal3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3HVNVPROC);
#define glNormal3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3IPROC);
#define glNormal3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3IVPROC);
#define glNormal3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3SPROC);
#define glNormal3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3SVPROC);
#define glNormal3xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3XOESPROC);
#define glNormal3xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMAL3XVOESPROC);
#define glNormalFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALFORMATNVPROC);
#define glNormalP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALP3UIPROC);
#define glNormalP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALP3UIVPROC);
#define glNormalPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALPOINTERPROC);
#define glNormalPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALPOINTEREXTPROC);
#define glNormalPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALPOINTERLISTIBMPROC);
#define glNormalPointervINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALPOINTERVINTELPROC);
#define glNormalStream3bATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3BATIPROC);
#define glNormalStream3bvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3BVATIPROC);
#define glNormalStream3dATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3DATIPROC);
#define glNormalStream3dvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3DVATIPROC);
#define glNormalStream3fATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3FATIPROC);
#define glNormalStream3fvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3FVATIPROC);
#define glNormalStream3iATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3IATIPROC);
#define glNormalStream3ivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3IVATIPROC);
#define glNormalStream3sATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3SATIPROC);
#define glNormalStream3svATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLNORMALSTREAM3SVATIPROC);
#define glObjectLabel(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLOBJECTLABELPROC);
#define glObjectPtrLabel(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLOBJECTPTRLABELPROC);
#define glObjectPurgeableAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLOBJECTPURGEABLEAPPLEPROC);
#define glObjectUnpurgeableAPPLE(...) (0)
typedef JELLO_GRADER_PROC(PFNGLOBJECTUNPURGEABLEAPPLEPROC);
#define glOrtho(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLORTHOPROC);
#define glOrthofOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLORTHOFOESPROC);
#define glOrthoxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLORTHOXOESPROC);
#define glPNTrianglesfATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPNTRIANGLESFATIPROC);
#define glPNTrianglesiATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPNTRIANGLESIATIPROC);
#define glPassTexCoordATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPASSTEXCOORDATIPROC);
#define glPassThrough(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPASSTHROUGHPROC);
#define glPassThroughxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPASSTHROUGHXOESPROC);
#define glPatchParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATCHPARAMETERFVPROC);
#define glPatchParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATCHPARAMETERIPROC);
#define glPathColorGenNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHCOLORGENNVPROC);
#define glPathCommandsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHCOMMANDSNVPROC);
#define glPathCoordsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHCOORDSNVPROC);
#define glPathCoverDepthFuncNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHCOVERDEPTHFUNCNVPROC);
#define glPathDashArrayNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHDASHARRAYNVPROC);
#define glPathFogGenNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHFOGGENNVPROC);
#define glPathGlyphIndexArrayNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLPATHGLYPHINDEXARRAYNVPROC);
#define glPathGlyphIndexRangeNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLPATHGLYPHINDEXRANGENVPROC);
#define glPathGlyphRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHGLYPHRANGENVPROC);
#define glPathGlyphsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHGLYPHSNVPROC);
#define glPathMemoryGlyphIndexArrayNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLPATHMEMORYGLYPHINDEXARRAYNVPROC);
#define glPathParameterfNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHPARAMETERFNVPROC);
#define glPathParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHPARAMETERFVNVPROC);
#define glPathParameteriNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHPARAMETERINVPROC);
#define glPathParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHPARAMETERIVNVPROC);
#define glPathStencilDepthOffsetNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHSTENCILDEPTHOFFSETNVPROC);
#define glPathStencilFuncNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHSTENCILFUNCNVPROC);
#define glPathStringNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHSTRINGNVPROC);
#define glPathSubCommandsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHSUBCOMMANDSNVPROC);
#define glPathSubCoordsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHSUBCOORDSNVPROC);
#define glPathTexGenNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPATHTEXGENNVPROC);
#define glPauseTransformFeedback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPAUSETRANSFORMFEEDBACKPROC);
#define glPauseTransformFeedbackNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPAUSETRANSFORMFEEDBACKNVPROC);
#define glPixelDataRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELDATARANGENVPROC);
#define glPixelMapfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELMAPFVPROC);
#define glPixelMapuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELMAPUIVPROC);
#define glPixelMapusv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELMAPUSVPROC);
#define glPixelMapx(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELMAPXPROC);
#define glPixelStoref(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELSTOREFPROC);
#define glPixelStorei(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELSTOREIPROC);
#define glPixelStorex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELSTOREXPROC);
#define glPixelTexGenParameterfSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTEXGENPARAMETERFSGISPROC);
#define glPixelTexGenParameterfvSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTEXGENPARAMETERFVSGISPROC);
#define glPixelTexGenParameteriSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTEXGENPARAMETERISGISPROC);
#define glPixelTexGenParameterivSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTEXGENPARAMETERIVSGISPROC);
#define glPixelTexGenSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTEXGENSGIXPROC);
#define glPixelTransferf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFERFPROC);
#define glPixelTransferi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFERIPROC);
#define glPixelTransferxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFERXOESPROC);
#define glPixelTransformParameterfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFORMPARAMETERFEXTPROC);
#define glPixelTransformParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFORMPARAMETERFVEXTPROC);
#define glPixelTransformParameteriEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFORMPARAMETERIEXTPROC);
#define glPixelTransformParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELTRANSFORMPARAMETERIVEXTPROC);
#define glPixelZoom(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELZOOMPROC);
#define glPixelZoomxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPIXELZOOMXOESPROC);
#define glPointAlongPathNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLPOINTALONGPATHNVPROC);
#define glPointParameterf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFPROC);
#define glPointParameterfARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFARBPROC);
#define glPointParameterfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFEXTPROC);
#define glPointParameterfSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFSGISPROC);
#define glPointParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFVPROC);
#define glPointParameterfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFVARBPROC);
#define glPointParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFVEXTPROC);
#define glPointParameterfvSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERFVSGISPROC);
#define glPointParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERIPROC);
#define glPointParameteriNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERINVPROC);
#define glPointParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERIVPROC);
#define glPointParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERIVNVPROC);
#define glPointParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTPARAMETERXVOESPROC);
#define glPointSize(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTSIZEPROC);
#define glPointSizexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOINTSIZEXOESPROC);
#define glPollAsyncSGIX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLPOLLASYNCSGIXPROC);
#define glPollInstrumentsSGIX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLPOLLINSTRUMENTSSGIXPROC);
#define glPolygonMode(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONMODEPROC);
#define glPolygonOffset(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONOFFSETPROC);
#define glPolygonOffsetClamp(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONOFFSETCLAMPPROC);
#define glPolygonOffsetClampEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONOFFSETCLAMPEXTPROC);
#define glPolygonOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONOFFSETEXTPROC);
#define glPolygonOffsetxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONOFFSETXOESPROC);
#define glPolygonStipple(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOLYGONSTIPPLEPROC);
#define glPopAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOPATTRIBPROC);
#define glPopClientAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOPCLIENTATTRIBPROC);
#define glPopDebugGroup(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOPDEBUGGROUPPROC);
#define glPopGroupMarkerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOPGROUPMARKEREXTPROC);
#define glPopMatrix(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOPMATRIXPROC);
#define glPopName(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPOPNAMEPROC);
#define glPresentFrameDualFillNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRESENTFRAMEDUALFILLNVPROC);
#define glPresentFrameKeyedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRESENTFRAMEKEYEDNVPROC);
#define glPrimitiveBoundingBoxARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIMITIVEBOUNDINGBOXARBPROC);
#define glPrimitiveRestartIndex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIMITIVERESTARTINDEXPROC);
#define glPrimitiveRestartIndexNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIMITIVERESTARTINDEXNVPROC);
#define glPrimitiveRestartNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIMITIVERESTARTNVPROC);
#define glPrioritizeTextures(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIORITIZETEXTURESPROC);
#define glPrioritizeTexturesEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIORITIZETEXTURESEXTPROC);
#define glPrioritizeTexturesxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPRIORITIZETEXTURESXOESPROC);
#define glProgramBinary(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMBINARYPROC);
#define glProgramBufferParametersIivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMBUFFERPARAMETERSIIVNVPROC);
#define glProgramBufferParametersIuivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMBUFFERPARAMETERSIUIVNVPROC);
#define glProgramBufferParametersfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMBUFFERPARAMETERSFVNVPROC);
#define glProgramEnvParameter4dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETER4DARBPROC);
#define glProgramEnvParameter4dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETER4DVARBPROC);
#define glProgramEnvParameter4fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETER4FARBPROC);
#define glProgramEnvParameter4fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETER4FVARBPROC);
#define glProgramEnvParameterI4iNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERI4INVPROC);
#define glProgramEnvParameterI4ivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERI4IVNVPROC);
#define glProgramEnvParameterI4uiNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERI4UINVPROC);
#define glProgramEnvParameterI4uivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERI4UIVNVPROC);
#define glProgramEnvParameters4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERS4FVEXTPROC);
#define glProgramEnvParametersI4ivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERSI4IVNVPROC);
#define glProgramEnvParametersI4uivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMENVPARAMETERSI4UIVNVPROC);
#define glProgramLocalParameter4dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETER4DARBPROC);
#define glProgramLocalParameter4dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETER4DVARBPROC);
#define glProgramLocalParameter4fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETER4FARBPROC);
#define glProgramLocalParameter4fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETER4FVARBPROC);
#define glProgramLocalParameterI4iNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERI4INVPROC);
#define glProgramLocalParameterI4ivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERI4IVNVPROC);
#define glProgramLocalParameterI4uiNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERI4UINVPROC);
#define glProgramLocalParameterI4uivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERI4UIVNVPROC);
#define glProgramLocalParameters4fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLPROGRAMLOCALPARAMETERS4FVEXTPROC);
