/* jello-grader-gl-functions-1.h: the GL, GLU and GLUT functions of the grader's GL stand-in
   (jello-grader-gl.h), a part of at most 60000 bytes: each file built into the
   grader stays a string under 64 kB. Made by scripts/make-gl-standins. */
#define glAccum(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACCUMPROC);
#define glAccumxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACCUMXOESPROC);
#define glAcquireKeyedMutexWin32EXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLACQUIREKEYEDMUTEXWIN32EXTPROC);
#define glActiveProgramEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACTIVEPROGRAMEXTPROC);
#define glActiveShaderProgram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACTIVESHADERPROGRAMPROC);
#define glActiveStencilFaceEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACTIVESTENCILFACEEXTPROC);
#define glActiveTexture(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACTIVETEXTUREPROC);
#define glActiveTextureARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACTIVETEXTUREARBPROC);
#define glActiveVaryingNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLACTIVEVARYINGNVPROC);
#define glAlphaFragmentOp1ATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLALPHAFRAGMENTOP1ATIPROC);
#define glAlphaFragmentOp2ATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLALPHAFRAGMENTOP2ATIPROC);
#define glAlphaFragmentOp3ATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLALPHAFRAGMENTOP3ATIPROC);
#define glAlphaFunc(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLALPHAFUNCPROC);
#define glAlphaFuncxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLALPHAFUNCXOESPROC);
#define glAlphaToCoverageDitherControlNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLALPHATOCOVERAGEDITHERCONTROLNVPROC);
#define glApplyFramebufferAttachmentCMAAINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLAPPLYFRAMEBUFFERATTACHMENTCMAAINTELPROC);
#define glApplyTextureEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLAPPLYTEXTUREEXTPROC);
#define glAreProgramsResidentNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLAREPROGRAMSRESIDENTNVPROC);
#define glAreTexturesResident(...) (0)
typedef JELLO_GRADER_PROC(PFNGLARETEXTURESRESIDENTPROC);
#define glAreTexturesResidentEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLARETEXTURESRESIDENTEXTPROC);
#define glArrayElement(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLARRAYELEMENTPROC);
#define glArrayElementEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLARRAYELEMENTEXTPROC);
#define glArrayObjectATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLARRAYOBJECTATIPROC);
#define glAsyncCopyBufferSubDataNVX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLASYNCCOPYBUFFERSUBDATANVXPROC);
#define glAsyncCopyImageSubDataNVX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLASYNCCOPYIMAGESUBDATANVXPROC);
#define glAsyncMarkerSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLASYNCMARKERSGIXPROC);
#define glAttachObjectARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLATTACHOBJECTARBPROC);
#define glAttachShader(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLATTACHSHADERPROC);
#define glBegin(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINPROC);
#define glBeginConditionalRender(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINCONDITIONALRENDERPROC);
#define glBeginConditionalRenderNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINCONDITIONALRENDERNVPROC);
#define glBeginConditionalRenderNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINCONDITIONALRENDERNVXPROC);
#define glBeginFragmentShaderATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINFRAGMENTSHADERATIPROC);
#define glBeginOcclusionQueryNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINOCCLUSIONQUERYNVPROC);
#define glBeginPerfMonitorAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINPERFMONITORAMDPROC);
#define glBeginPerfQueryINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINPERFQUERYINTELPROC);
#define glBeginQuery(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINQUERYPROC);
#define glBeginQueryARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINQUERYARBPROC);
#define glBeginQueryIndexed(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINQUERYINDEXEDPROC);
#define glBeginTransformFeedback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINTRANSFORMFEEDBACKPROC);
#define glBeginTransformFeedbackEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINTRANSFORMFEEDBACKEXTPROC);
#define glBeginTransformFeedbackNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINTRANSFORMFEEDBACKNVPROC);
#define glBeginVertexShaderEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINVERTEXSHADEREXTPROC);
#define glBeginVideoCaptureNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBEGINVIDEOCAPTURENVPROC);
#define glBindAttribLocation(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDATTRIBLOCATIONPROC);
#define glBindAttribLocationARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDATTRIBLOCATIONARBPROC);
#define glBindBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERPROC);
#define glBindBufferARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERARBPROC);
#define glBindBufferBase(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERBASEPROC);
#define glBindBufferBaseEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERBASEEXTPROC);
#define glBindBufferBaseNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERBASENVPROC);
#define glBindBufferOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFEROFFSETEXTPROC);
#define glBindBufferOffsetNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFEROFFSETNVPROC);
#define glBindBufferRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERRANGEPROC);
#define glBindBufferRangeEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERRANGEEXTPROC);
#define glBindBufferRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERRANGENVPROC);
#define glBindBuffersBase(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERSBASEPROC);
#define glBindBuffersRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDBUFFERSRANGEPROC);
#define glBindFragDataLocation(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDFRAGDATALOCATIONPROC);
#define glBindFragDataLocationEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDFRAGDATALOCATIONEXTPROC);
#define glBindFragDataLocationIndexed(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDFRAGDATALOCATIONINDEXEDPROC);
#define glBindFragmentShaderATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDFRAGMENTSHADERATIPROC);
#define glBindFramebuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDFRAMEBUFFERPROC);
#define glBindFramebufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDFRAMEBUFFEREXTPROC);
#define glBindImageTexture(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDIMAGETEXTUREPROC);
#define glBindImageTextureEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDIMAGETEXTUREEXTPROC);
#define glBindImageTextures(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDIMAGETEXTURESPROC);
#define glBindLightParameterEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLBINDLIGHTPARAMETEREXTPROC);
#define glBindMaterialParameterEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLBINDMATERIALPARAMETEREXTPROC);
#define glBindMultiTextureEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDMULTITEXTUREEXTPROC);
#define glBindParameterEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLBINDPARAMETEREXTPROC);
#define glBindProgramARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDPROGRAMARBPROC);
#define glBindProgramNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDPROGRAMNVPROC);
#define glBindProgramPipeline(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDPROGRAMPIPELINEPROC);
#define glBindRenderbuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDRENDERBUFFERPROC);
#define glBindRenderbufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDRENDERBUFFEREXTPROC);
#define glBindSampler(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDSAMPLERPROC);
#define glBindSamplers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDSAMPLERSPROC);
#define glBindShadingRateImageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDSHADINGRATEIMAGENVPROC);
#define glBindTexGenParameterEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLBINDTEXGENPARAMETEREXTPROC);
#define glBindTexture(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDTEXTUREPROC);
#define glBindTextureEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDTEXTUREEXTPROC);
#define glBindTextureUnit(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDTEXTUREUNITPROC);
#define glBindTextureUnitParameterEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLBINDTEXTUREUNITPARAMETEREXTPROC);
#define glBindTextures(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDTEXTURESPROC);
#define glBindTransformFeedback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDTRANSFORMFEEDBACKPROC);
#define glBindTransformFeedbackNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDTRANSFORMFEEDBACKNVPROC);
#define glBindVertexArray(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVERTEXARRAYPROC);
#define glBindVertexArrayAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVERTEXARRAYAPPLEPROC);
#define glBindVertexBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVERTEXBUFFERPROC);
#define glBindVertexBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVERTEXBUFFERSPROC);
#define glBindVertexShaderEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVERTEXSHADEREXTPROC);
#define glBindVideoCaptureStreamBufferNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVIDEOCAPTURESTREAMBUFFERNVPROC);
#define glBindVideoCaptureStreamTextureNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINDVIDEOCAPTURESTREAMTEXTURENVPROC);
#define glBinormal3bEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3BEXTPROC);
#define glBinormal3bvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3BVEXTPROC);
#define glBinormal3dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3DEXTPROC);
#define glBinormal3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3DVEXTPROC);
#define glBinormal3fEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3FEXTPROC);
#define glBinormal3fvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3FVEXTPROC);
#define glBinormal3iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3IEXTPROC);
#define glBinormal3ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3IVEXTPROC);
#define glBinormal3sEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3SEXTPROC);
#define glBinormal3svEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMAL3SVEXTPROC);
#define glBinormalPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBINORMALPOINTEREXTPROC);
#define glBitmap(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBITMAPPROC);
#define glBitmapxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBITMAPXOESPROC);
#define glBlendBarrierKHR(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDBARRIERKHRPROC);
#define glBlendBarrierNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDBARRIERNVPROC);
#define glBlendColor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDCOLORPROC);
#define glBlendColorEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDCOLOREXTPROC);
#define glBlendColorxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDCOLORXOESPROC);
#define glBlendEquation(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONPROC);
#define glBlendEquationEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONEXTPROC);
#define glBlendEquationIndexedAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONINDEXEDAMDPROC);
#define glBlendEquationSeparate(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONSEPARATEPROC);
#define glBlendEquationSeparateATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONSEPARATEATIPROC);
#define glBlendEquationSeparateEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONSEPARATEEXTPROC);
#define glBlendEquationSeparateIndexedAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONSEPARATEINDEXEDAMDPROC);
#define glBlendEquationSeparatei(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONSEPARATEIPROC);
#define glBlendEquationSeparateiARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONSEPARATEIARBPROC);
#define glBlendEquationi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONIPROC);
#define glBlendEquationiARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDEQUATIONIARBPROC);
#define glBlendFunc(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCPROC);
#define glBlendFuncIndexedAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCINDEXEDAMDPROC);
#define glBlendFuncSeparate(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCSEPARATEPROC);
#define glBlendFuncSeparateEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCSEPARATEEXTPROC);
#define glBlendFuncSeparateINGR(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCSEPARATEINGRPROC);
#define glBlendFuncSeparateIndexedAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCSEPARATEINDEXEDAMDPROC);
#define glBlendFuncSeparatei(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCSEPARATEIPROC);
#define glBlendFuncSeparateiARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCSEPARATEIARBPROC);
#define glBlendFunci(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCIPROC);
#define glBlendFunciARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDFUNCIARBPROC);
#define glBlendParameteriNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLENDPARAMETERINVPROC);
#define glBlitFramebuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLITFRAMEBUFFERPROC);
#define glBlitFramebufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLITFRAMEBUFFEREXTPROC);
#define glBlitNamedFramebuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBLITNAMEDFRAMEBUFFERPROC);
#define glBufferAddressRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERADDRESSRANGENVPROC);
#define glBufferAttachMemoryNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERATTACHMEMORYNVPROC);
#define glBufferData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERDATAPROC);
#define glBufferDataARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERDATAARBPROC);
#define glBufferPageCommitmentARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERPAGECOMMITMENTARBPROC);
#define glBufferPageCommitmentMemNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERPAGECOMMITMENTMEMNVPROC);
#define glBufferParameteriAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERPARAMETERIAPPLEPROC);
#define glBufferStorage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERSTORAGEPROC);
#define glBufferStorageExternalEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERSTORAGEEXTERNALEXTPROC);
#define glBufferStorageMemEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERSTORAGEMEMEXTPROC);
#define glBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERSUBDATAPROC);
#define glBufferSubDataARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLBUFFERSUBDATAARBPROC);
#define glCallCommandListNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCALLCOMMANDLISTNVPROC);
#define glCallList(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCALLLISTPROC);
#define glCallLists(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCALLLISTSPROC);
#define glCheckFramebufferStatus(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCHECKFRAMEBUFFERSTATUSPROC);
#define glCheckFramebufferStatusEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCHECKFRAMEBUFFERSTATUSEXTPROC);
#define glCheckNamedFramebufferStatus(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC);
#define glCheckNamedFramebufferStatusEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSEXTPROC);
#define glClampColor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLAMPCOLORPROC);
#define glClampColorARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLAMPCOLORARBPROC);
#define glClear(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARPROC);
#define glClearAccum(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARACCUMPROC);
#define glClearAccumxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARACCUMXOESPROC);
#define glClearBufferData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARBUFFERDATAPROC);
#define glClearBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARBUFFERSUBDATAPROC);
#define glClearBufferfi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARBUFFERFIPROC);
#define glClearBufferfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARBUFFERFVPROC);
#define glClearBufferiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARBUFFERIVPROC);
#define glClearBufferuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARBUFFERUIVPROC);
#define glClearColor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARCOLORPROC);
#define glClearColorIiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARCOLORIIEXTPROC);
#define glClearColorIuiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARCOLORIUIEXTPROC);
#define glClearColorxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARCOLORXOESPROC);
#define glClearDepth(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARDEPTHPROC);
#define glClearDepthdNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARDEPTHDNVPROC);
#define glClearDepthf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARDEPTHFPROC);
#define glClearDepthfOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARDEPTHFOESPROC);
#define glClearDepthxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARDEPTHXOESPROC);
#define glClearIndex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARINDEXPROC);
#define glClearNamedBufferData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDBUFFERDATAPROC);
#define glClearNamedBufferDataEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDBUFFERDATAEXTPROC);
#define glClearNamedBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDBUFFERSUBDATAPROC);
#define glClearNamedBufferSubDataEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDBUFFERSUBDATAEXTPROC);
#define glClearNamedFramebufferfi(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDFRAMEBUFFERFIPROC);
#define glClearNamedFramebufferfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDFRAMEBUFFERFVPROC);
#define glClearNamedFramebufferiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDFRAMEBUFFERIVPROC);
#define glClearNamedFramebufferuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARNAMEDFRAMEBUFFERUIVPROC);
#define glClearStencil(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARSTENCILPROC);
#define glClearTexImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARTEXIMAGEPROC);
#define glClearTexSubImage(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLEARTEXSUBIMAGEPROC);
#define glClientActiveTexture(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIENTACTIVETEXTUREPROC);
#define glClientActiveTextureARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIENTACTIVETEXTUREARBPROC);
#define glClientActiveVertexStreamATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIENTACTIVEVERTEXSTREAMATIPROC);
#define glClientAttribDefaultEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIENTATTRIBDEFAULTEXTPROC);
#define glClientWaitSemaphoreui64NVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIENTWAITSEMAPHOREUI64NVXPROC);
#define glClientWaitSync(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCLIENTWAITSYNCPROC);
#define glClipControl(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIPCONTROLPROC);
#define glClipPlane(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIPPLANEPROC);
#define glClipPlanefOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIPPLANEFOESPROC);
#define glClipPlanexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCLIPPLANEXOESPROC);
#define glColor3b(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3BPROC);
#define glColor3bv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3BVPROC);
#define glColor3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3DPROC);
#define glColor3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3DVPROC);
#define glColor3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3FPROC);
#define glColor3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3FVERTEX3FSUNPROC);
#define glColor3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3FVERTEX3FVSUNPROC);
#define glColor3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3FVPROC);
#define glColor3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3HNVPROC);
#define glColor3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3HVNVPROC);
#define glColor3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3IPROC);
#define glColor3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3IVPROC);
#define glColor3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3SPROC);
#define glColor3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3SVPROC);
#define glColor3ub(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3UBPROC);
#define glColor3ubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3UBVPROC);
#define glColor3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3UIPROC);
#define glColor3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3UIVPROC);
#define glColor3us(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3USPROC);
#define glColor3usv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3USVPROC);
#define glColor3xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3XOESPROC);
#define glColor3xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR3XVOESPROC);
#define glColor4b(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4BPROC);
#define glColor4bv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4BVPROC);
#define glColor4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4DPROC);
#define glColor4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4DVPROC);
#define glColor4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4FPROC);
#define glColor4fNormal3fVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4FNORMAL3FVERTEX3FSUNPROC);
#define glColor4fNormal3fVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4FNORMAL3FVERTEX3FVSUNPROC);
#define glColor4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4FVPROC);
#define glColor4hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4HNVPROC);
#define glColor4hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4HVNVPROC);
#define glColor4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4IPROC);
#define glColor4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4IVPROC);
#define glColor4s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4SPROC);
#define glColor4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4SVPROC);
#define glColor4ub(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UBPROC);
#define glColor4ubVertex2fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UBVERTEX2FSUNPROC);
#define glColor4ubVertex2fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UBVERTEX2FVSUNPROC);
#define glColor4ubVertex3fSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UBVERTEX3FSUNPROC);
#define glColor4ubVertex3fvSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UBVERTEX3FVSUNPROC);
#define glColor4ubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UBVPROC);
#define glColor4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UIPROC);
#define glColor4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4UIVPROC);
#define glColor4us(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4USPROC);
#define glColor4usv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4USVPROC);
#define glColor4xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4XOESPROC);
#define glColor4xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLOR4XVOESPROC);
#define glColorFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORFORMATNVPROC);
#define glColorFragmentOp1ATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORFRAGMENTOP1ATIPROC);
#define glColorFragmentOp2ATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORFRAGMENTOP2ATIPROC);
#define glColorFragmentOp3ATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORFRAGMENTOP3ATIPROC);
#define glColorMask(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORMASKPROC);
#define glColorMaskIndexedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORMASKINDEXEDEXTPROC);
#define glColorMaski(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORMASKIPROC);
#define glColorMaterial(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORMATERIALPROC);
#define glColorP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORP3UIPROC);
#define glColorP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORP3UIVPROC);
#define glColorP4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORP4UIPROC);
#define glColorP4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORP4UIVPROC);
#define glColorPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORPOINTERPROC);
#define glColorPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORPOINTEREXTPROC);
#define glColorPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORPOINTERLISTIBMPROC);
#define glColorPointervINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORPOINTERVINTELPROC);
#define glColorSubTable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORSUBTABLEPROC);
#define glColorSubTableEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORSUBTABLEEXTPROC);
#define glColorTable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLEPROC);
#define glColorTableEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLEEXTPROC);
#define glColorTableParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLEPARAMETERFVPROC);
#define glColorTableParameterfvSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLEPARAMETERFVSGIPROC);
#define glColorTableParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLEPARAMETERIVPROC);
#define glColorTableParameterivSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLEPARAMETERIVSGIPROC);
#define glColorTableSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOLORTABLESGIPROC);
#define glCombinerInputNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINERINPUTNVPROC);
#define glCombinerOutputNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINEROUTPUTNVPROC);
#define glCombinerParameterfNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINERPARAMETERFNVPROC);
#define glCombinerParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINERPARAMETERFVNVPROC);
#define glCombinerParameteriNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINERPARAMETERINVPROC);
#define glCombinerParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINERPARAMETERIVNVPROC);
#define glCombinerStageParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMBINERSTAGEPARAMETERFVNVPROC);
#define glCommandListSegmentsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMMANDLISTSEGMENTSNVPROC);
#define glCompileCommandListNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPILECOMMANDLISTNVPROC);
#define glCompileShader(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPILESHADERPROC);
#define glCompileShaderARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPILESHADERARBPROC);
#define glCompileShaderIncludeARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPILESHADERINCLUDEARBPROC);
#define glCompressedMultiTexImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDMULTITEXIMAGE1DEXTPROC);
#define glCompressedMultiTexImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDMULTITEXIMAGE2DEXTPROC);
#define glCompressedMultiTexImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDMULTITEXIMAGE3DEXTPROC);
#define glCompressedMultiTexSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDMULTITEXSUBIMAGE1DEXTPROC);
#define glCompressedMultiTexSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDMULTITEXSUBIMAGE2DEXTPROC);
#define glCompressedMultiTexSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDMULTITEXSUBIMAGE3DEXTPROC);
#define glCompressedTexImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXIMAGE1DPROC);
#define glCompressedTexImage1DARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXIMAGE1DARBPROC);
#define glCompressedTexImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXIMAGE2DPROC);
#define glCompressedTexImage2DARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXIMAGE2DARBPROC);
#define glCompressedTexImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXIMAGE3DPROC);
#define glCompressedTexImage3DARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXIMAGE3DARBPROC);
#define glCompressedTexSubImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXSUBIMAGE1DPROC);
#define glCompressedTexSubImage1DARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXSUBIMAGE1DARBPROC);
#define glCompressedTexSubImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXSUBIMAGE2DPROC);
#define glCompressedTexSubImage2DARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXSUBIMAGE2DARBPROC);
#define glCompressedTexSubImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXSUBIMAGE3DPROC);
#define glCompressedTexSubImage3DARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXSUBIMAGE3DARBPROC);
#define glCompressedTextureImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTUREIMAGE1DEXTPROC);
#define glCompressedTextureImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTUREIMAGE2DEXTPROC);
#define glCompressedTextureImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTUREIMAGE3DEXTPROC);
#define glCompressedTextureSubImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTURESUBIMAGE1DPROC);
#define glCompressedTextureSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTURESUBIMAGE1DEXTPROC);
#define glCompressedTextureSubImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTURESUBIMAGE2DPROC);
#define glCompressedTextureSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTURESUBIMAGE2DEXTPROC);
#define glCompressedTextureSubImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTURESUBIMAGE3DPROC);
#define glCompressedTextureSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOMPRESSEDTEXTURESUBIMAGE3DEXTPROC);
#define glConservativeRasterParameterfNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONSERVATIVERASTERPARAMETERFNVPROC);
#define glConservativeRasterParameteriNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONSERVATIVERASTERPARAMETERINVPROC);
#define glConvolutionFilter1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONFILTER1DPROC);
#define glConvolutionFilter1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONFILTER1DEXTPROC);
#define glConvolutionFilter2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONFILTER2DPROC);
#define glConvolutionFilter2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONFILTER2DEXTPROC);
#define glConvolutionParameterf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERFPROC);
#define glConvolutionParameterfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERFEXTPROC);
#define glConvolutionParameterfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERFVPROC);
#define glConvolutionParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERFVEXTPROC);
#define glConvolutionParameteri(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERIPROC);
#define glConvolutionParameteriEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERIEXTPROC);
#define glConvolutionParameteriv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERIVPROC);
#define glConvolutionParameterivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERIVEXTPROC);
#define glConvolutionParameterxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERXOESPROC);
#define glConvolutionParameterxvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCONVOLUTIONPARAMETERXVOESPROC);
#define glCopyBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYBUFFERSUBDATAPROC);
#define glCopyColorSubTable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCOLORSUBTABLEPROC);
#define glCopyColorSubTableEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCOLORSUBTABLEEXTPROC);
#define glCopyColorTable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCOLORTABLEPROC);
#define glCopyColorTableSGI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCOLORTABLESGIPROC);
#define glCopyConvolutionFilter1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCONVOLUTIONFILTER1DPROC);
#define glCopyConvolutionFilter1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCONVOLUTIONFILTER1DEXTPROC);
#define glCopyConvolutionFilter2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCONVOLUTIONFILTER2DPROC);
#define glCopyConvolutionFilter2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYCONVOLUTIONFILTER2DEXTPROC);
#define glCopyImageSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYIMAGESUBDATAPROC);
#define glCopyImageSubDataNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYIMAGESUBDATANVPROC);
#define glCopyMultiTexImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYMULTITEXIMAGE1DEXTPROC);
#define glCopyMultiTexImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYMULTITEXIMAGE2DEXTPROC);
#define glCopyMultiTexSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYMULTITEXSUBIMAGE1DEXTPROC);
#define glCopyMultiTexSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYMULTITEXSUBIMAGE2DEXTPROC);
#define glCopyMultiTexSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYMULTITEXSUBIMAGE3DEXTPROC);
#define glCopyNamedBufferSubData(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYNAMEDBUFFERSUBDATAPROC);
#define glCopyPathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYPATHNVPROC);
#define glCopyPixels(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYPIXELSPROC);
#define glCopyTexImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXIMAGE1DPROC);
#define glCopyTexImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXIMAGE1DEXTPROC);
#define glCopyTexImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXIMAGE2DPROC);
#define glCopyTexImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXIMAGE2DEXTPROC);
#define glCopyTexSubImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXSUBIMAGE1DPROC);
#define glCopyTexSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXSUBIMAGE1DEXTPROC);
#define glCopyTexSubImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXSUBIMAGE2DPROC);
#define glCopyTexSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXSUBIMAGE2DEXTPROC);
#define glCopyTexSubImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXSUBIMAGE3DPROC);
#define glCopyTexSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXSUBIMAGE3DEXTPROC);
#define glCopyTextureImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTUREIMAGE1DEXTPROC);
#define glCopyTextureImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTUREIMAGE2DEXTPROC);
#define glCopyTextureSubImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTURESUBIMAGE1DPROC);
#define glCopyTextureSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTURESUBIMAGE1DEXTPROC);
#define glCopyTextureSubImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTURESUBIMAGE2DPROC);
#define glCopyTextureSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTURESUBIMAGE2DEXTPROC);
#define glCopyTextureSubImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTURESUBIMAGE3DPROC);
#define glCopyTextureSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOPYTEXTURESUBIMAGE3DEXTPROC);
#define glCoverFillPathInstancedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOVERFILLPATHINSTANCEDNVPROC);
#define glCoverFillPathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOVERFILLPATHNVPROC);
#define glCoverStrokePathInstancedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOVERSTROKEPATHINSTANCEDNVPROC);
#define glCoverStrokePathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOVERSTROKEPATHNVPROC);
#define glCoverageModulationNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOVERAGEMODULATIONNVPROC);
#define glCoverageModulationTableNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCOVERAGEMODULATIONTABLENVPROC);
#define glCreateBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEBUFFERSPROC);
#define glCreateCommandListsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATECOMMANDLISTSNVPROC);
#define glCreateFramebuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEFRAMEBUFFERSPROC);
#define glCreateMemoryObjectsEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEMEMORYOBJECTSEXTPROC);
#define glCreatePerfQueryINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEPERFQUERYINTELPROC);
#define glCreateProgram(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATEPROGRAMPROC);
#define glCreateProgramObjectARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATEPROGRAMOBJECTARBPROC);
#define glCreateProgramPipelines(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEPROGRAMPIPELINESPROC);
#define glCreateProgressFenceNVX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATEPROGRESSFENCENVXPROC);
#define glCreateQueries(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEQUERIESPROC);
#define glCreateRenderbuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATERENDERBUFFERSPROC);
#define glCreateSamplers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATESAMPLERSPROC);
#define glCreateSemaphoresNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATESEMAPHORESNVPROC);
#define glCreateShader(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATESHADERPROC);
#define glCreateShaderObjectARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATESHADEROBJECTARBPROC);
#define glCreateShaderProgramEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATESHADERPROGRAMEXTPROC);
#define glCreateShaderProgramv(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATESHADERPROGRAMVPROC);
#define glCreateStatesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATESTATESNVPROC);
#define glCreateSyncFromCLeventARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLCREATESYNCFROMCLEVENTARBPROC);
#define glCreateTextures(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATETEXTURESPROC);
#define glCreateTransformFeedbacks(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATETRANSFORMFEEDBACKSPROC);
#define glCreateVertexArrays(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCREATEVERTEXARRAYSPROC);
#define glCullFace(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCULLFACEPROC);
#define glCullParameterdvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCULLPARAMETERDVEXTPROC);
#define glCullParameterfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCULLPARAMETERFVEXTPROC);
#define glCurrentPaletteMatrixARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLCURRENTPALETTEMATRIXARBPROC);
#define glDebugMessageCallback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGECALLBACKPROC);
#define glDebugMessageCallbackAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGECALLBACKAMDPROC);
#define glDebugMessageCallbackARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGECALLBACKARBPROC);
#define glDebugMessageControl(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGECONTROLPROC);
#define glDebugMessageControlARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGECONTROLARBPROC);
#define glDebugMessageEnableAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGEENABLEAMDPROC);
#define glDebugMessageInsert(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGEINSERTPROC);
#define glDebugMessageInsertAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGEINSERTAMDPROC);
#define glDebugMessageInsertARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEBUGMESSAGEINSERTARBPROC);
#define glDeformSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEFORMSGIXPROC);
#define glDeformationMap3dSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEFORMATIONMAP3DSGIXPROC);
#define glDeformationMap3fSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEFORMATIONMAP3FSGIXPROC);
#define glDeleteAsyncMarkersSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEASYNCMARKERSSGIXPROC);
#define glDeleteBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEBUFFERSPROC);
#define glDeleteBuffersARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEBUFFERSARBPROC);
#define glDeleteCommandListsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETECOMMANDLISTSNVPROC);
#define glDeleteFencesAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEFENCESAPPLEPROC);
#define glDeleteFencesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEFENCESNVPROC);
#define glDeleteFragmentShaderATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEFRAGMENTSHADERATIPROC);
#define glDeleteFramebuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEFRAMEBUFFERSPROC);
#define glDeleteFramebuffersEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEFRAMEBUFFERSEXTPROC);
#define glDeleteLists(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETELISTSPROC);
#define glDeleteMemoryObjectsEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEMEMORYOBJECTSEXTPROC);
#define glDeleteNamedStringARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETENAMEDSTRINGARBPROC);
#define glDeleteNamesAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETENAMESAMDPROC);
#define glDeleteObjectARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEOBJECTARBPROC);
#define glDeleteOcclusionQueriesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEOCCLUSIONQUERIESNVPROC);
#define glDeletePathsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPATHSNVPROC);
#define glDeletePerfMonitorsAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPERFMONITORSAMDPROC);
#define glDeletePerfQueryINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPERFQUERYINTELPROC);
#define glDeleteProgram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPROGRAMPROC);
#define glDeleteProgramPipelines(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPROGRAMPIPELINESPROC);
#define glDeleteProgramsARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPROGRAMSARBPROC);
#define glDeleteProgramsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEPROGRAMSNVPROC);
#define glDeleteQueries(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEQUERIESPROC);
#define glDeleteQueriesARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEQUERIESARBPROC);
#define glDeleteQueryResourceTagNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEQUERYRESOURCETAGNVPROC);
#define glDeleteRenderbuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETERENDERBUFFERSPROC);
#define glDeleteRenderbuffersEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETERENDERBUFFERSEXTPROC);
#define glDeleteSamplers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETESAMPLERSPROC);
#define glDeleteSemaphoresEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETESEMAPHORESEXTPROC);
#define glDeleteShader(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETESHADERPROC);
#define glDeleteStatesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETESTATESNVPROC);
#define glDeleteSync(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETESYNCPROC);
#define glDeleteTextures(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETETEXTURESPROC);
#define glDeleteTexturesEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETETEXTURESEXTPROC);
#define glDeleteTransformFeedbacks(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETETRANSFORMFEEDBACKSPROC);
#define glDeleteTransformFeedbacksNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETETRANSFORMFEEDBACKSNVPROC);
#define glDeleteVertexArrays(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEVERTEXARRAYSPROC);
#define glDeleteVertexArraysAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEVERTEXARRAYSAPPLEPROC);
#define glDeleteVertexShaderEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDELETEVERTEXSHADEREXTPROC);
#define glDepthBoundsEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHBOUNDSEXTPROC);
#define glDepthBoundsdNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHBOUNDSDNVPROC);
#define glDepthFunc(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHFUNCPROC);
#define glDepthMask(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHMASKPROC);
#define glDepthRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEPROC);
#define glDepthRangeArraydvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEARRAYDVNVPROC);
#define glDepthRangeArrayv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEARRAYVPROC);
#define glDepthRangeIndexed(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEINDEXEDPROC);
#define glDepthRangeIndexeddNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEINDEXEDDNVPROC);
#define glDepthRangedNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEDNVPROC);
#define glDepthRangef(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEFPROC);
#define glDepthRangefOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEFOESPROC);
#define glDepthRangexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDEPTHRANGEXOESPROC);
#define glDetachObjectARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDETACHOBJECTARBPROC);
#define glDetachShader(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDETACHSHADERPROC);
#define glDetailTexFuncSGIS(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDETAILTEXFUNCSGISPROC);
#define glDisable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEPROC);
#define glDisableClientState(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLECLIENTSTATEPROC);
#define glDisableClientStateIndexedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLECLIENTSTATEINDEXEDEXTPROC);
#define glDisableClientStateiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLECLIENTSTATEIEXTPROC);
#define glDisableIndexedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEINDEXEDEXTPROC);
#define glDisableVariantClientStateEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVARIANTCLIENTSTATEEXTPROC);
#define glDisableVertexArrayAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVERTEXARRAYATTRIBPROC);
#define glDisableVertexArrayAttribEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVERTEXARRAYATTRIBEXTPROC);
#define glDisableVertexArrayEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVERTEXARRAYEXTPROC);
#define glDisableVertexAttribAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVERTEXATTRIBAPPLEPROC);
#define glDisableVertexAttribArray(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVERTEXATTRIBARRAYPROC);
#define glDisableVertexAttribArrayARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEVERTEXATTRIBARRAYARBPROC);
#define glDisablei(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISABLEIPROC);
#define glDispatchCompute(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISPATCHCOMPUTEPROC);
#define glDispatchComputeGroupSizeARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISPATCHCOMPUTEGROUPSIZEARBPROC);
#define glDispatchComputeIndirect(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDISPATCHCOMPUTEINDIRECTPROC);
#define glDrawArrays(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSPROC);
#define glDrawArraysEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSEXTPROC);
#define glDrawArraysIndirect(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSINDIRECTPROC);
#define glDrawArraysInstanced(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSINSTANCEDPROC);
#define glDrawArraysInstancedARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSINSTANCEDARBPROC);
#define glDrawArraysInstancedBaseInstance(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSINSTANCEDBASEINSTANCEPROC);
#define glDrawArraysInstancedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWARRAYSINSTANCEDEXTPROC);
#define glDrawBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWBUFFERPROC);
#define glDrawBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWBUFFERSPROC);
#define glDrawBuffersARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWBUFFERSARBPROC);
#define glDrawBuffersATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWBUFFERSATIPROC);
#define glDrawCommandsAddressNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWCOMMANDSADDRESSNVPROC);
#define glDrawCommandsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWCOMMANDSNVPROC);
#define glDrawCommandsStatesAddressNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWCOMMANDSSTATESADDRESSNVPROC);
#define glDrawCommandsStatesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWCOMMANDSSTATESNVPROC);
#define glDrawElementArrayAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTARRAYAPPLEPROC);
#define glDrawElementArrayATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTARRAYATIPROC);
#define glDrawElements(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSPROC);
#define glDrawElementsBaseVertex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSBASEVERTEXPROC);
#define glDrawElementsIndirect(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINDIRECTPROC);
#define glDrawElementsInstanced(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINSTANCEDPROC);
#define glDrawElementsInstancedARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINSTANCEDARBPROC);
#define glDrawElementsInstancedBaseInstance(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINSTANCEDBASEINSTANCEPROC);
#define glDrawElementsInstancedBaseVertex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINSTANCEDBASEVERTEXPROC);
#define glDrawElementsInstancedBaseVertexBaseInstance(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINSTANCEDBASEVERTEXBASEINSTANCEPROC);
#define glDrawElementsInstancedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWELEMENTSINSTANCEDEXTPROC);
#define glDrawMeshArraysSUN(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWMESHARRAYSSUNPROC);
#define glDrawMeshTasksIndirectNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWMESHTASKSINDIRECTNVPROC);
#define glDrawMeshTasksNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWMESHTASKSNVPROC);
#define glDrawPixels(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWPIXELSPROC);
#define glDrawRangeElementArrayAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWRANGEELEMENTARRAYAPPLEPROC);
#define glDrawRangeElementArrayATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWRANGEELEMENTARRAYATIPROC);
#define glDrawRangeElements(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWRANGEELEMENTSPROC);
#define glDrawRangeElementsBaseVertex(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWRANGEELEMENTSBASEVERTEXPROC);
#define glDrawRangeElementsEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWRANGEELEMENTSEXTPROC);
#define glDrawTextureNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWTEXTURENVPROC);
#define glDrawTransformFeedback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWTRANSFORMFEEDBACKPROC);
#define glDrawTransformFeedbackInstanced(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWTRANSFORMFEEDBACKINSTANCEDPROC);
#define glDrawTransformFeedbackNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWTRANSFORMFEEDBACKNVPROC);
#define glDrawTransformFeedbackStream(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWTRANSFORMFEEDBACKSTREAMPROC);
#define glDrawTransformFeedbackStreamInstanced(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWTRANSFORMFEEDBACKSTREAMINSTANCEDPROC);
#define glDrawVkImageNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLDRAWVKIMAGENVPROC);
#define glEGLImageTargetRenderbufferStorageOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEGLIMAGETARGETRENDERBUFFERSTORAGEOESPROC);
#define glEGLImageTargetTexStorageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEGLIMAGETARGETTEXSTORAGEEXTPROC);
#define glEGLImageTargetTexture2DOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEGLIMAGETARGETTEXTURE2DOESPROC);
#define glEGLImageTargetTextureStorageEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEGLIMAGETARGETTEXTURESTORAGEEXTPROC);
#define glEdgeFlag(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEDGEFLAGPROC);
#define glEdgeFlagFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEDGEFLAGFORMATNVPROC);
#define glEdgeFlagPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEDGEFLAGPOINTERPROC);
#define glEdgeFlagPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEDGEFLAGPOINTEREXTPROC);
#define glEdgeFlagPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEDGEFLAGPOINTERLISTIBMPROC);
#define glEdgeFlagv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEDGEFLAGVPROC);
#define glElementPointerAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLELEMENTPOINTERAPPLEPROC);
#define glElementPointerATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLELEMENTPOINTERATIPROC);
#define glEnable(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEPROC);
#define glEnableClientState(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLECLIENTSTATEPROC);
#define glEnableClientStateIndexedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLECLIENTSTATEINDEXEDEXTPROC);
#define glEnableClientStateiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLECLIENTSTATEIEXTPROC);
#define glEnableIndexedEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEINDEXEDEXTPROC);
#define glEnableVariantClientStateEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVARIANTCLIENTSTATEEXTPROC);
#define glEnableVertexArrayAttrib(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVERTEXARRAYATTRIBPROC);
#define glEnableVertexArrayAttribEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVERTEXARRAYATTRIBEXTPROC);
#define glEnableVertexArrayEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVERTEXARRAYEXTPROC);
#define glEnableVertexAttribAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVERTEXATTRIBAPPLEPROC);
#define glEnableVertexAttribArray(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVERTEXATTRIBARRAYPROC);
#define glEnableVertexAttribArrayARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEVERTEXATTRIBARRAYARBPROC);
#define glEnablei(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENABLEIPROC);
#define glEnd(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDPROC);
#define glEndConditionalRender(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDCONDITIONALRENDERPROC);
#define glEndConditionalRenderNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDCONDITIONALRENDERNVPROC);
#define glEndConditionalRenderNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDCONDITIONALRENDERNVXPROC);
#define glEndFragmentShaderATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDFRAGMENTSHADERATIPROC);
#define glEndList(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDLISTPROC);
#define glEndOcclusionQueryNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDOCCLUSIONQUERYNVPROC);
#define glEndPerfMonitorAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDPERFMONITORAMDPROC);
#define glEndPerfQueryINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDPERFQUERYINTELPROC);
#define glEndQuery(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDQUERYPROC);
#define glEndQueryARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDQUERYARBPROC);
#define glEndQueryIndexed(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDQUERYINDEXEDPROC);
#define glEndTransformFeedback(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDTRANSFORMFEEDBACKPROC);
#define glEndTransformFeedbackEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDTRANSFORMFEEDBACKEXTPROC);
#define glEndTransformFeedbackNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDTRANSFORMFEEDBACKNVPROC);
#define glEndVertexShaderEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDVERTEXSHADEREXTPROC);
#define glEndVideoCaptureNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLENDVIDEOCAPTURENVPROC);
#define glEvalCoord1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD1DPROC);
#define glEvalCoord1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD1DVPROC);
#define glEvalCoord1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD1FPROC);
#define glEvalCoord1fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD1FVPROC);
#define glEvalCoord1xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD1XOESPROC);
#define glEvalCoord1xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD1XVOESPROC);
#define glEvalCoord2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD2DPROC);
#define glEvalCoord2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD2DVPROC);
#define glEvalCoord2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD2FPROC);
#define glEvalCoord2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD2FVPROC);
#define glEvalCoord2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD2XOESPROC);
#define glEvalCoord2xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALCOORD2XVOESPROC);
#define glEvalMapsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALMAPSNVPROC);
#define glEvalMesh1(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALMESH1PROC);
#define glEvalMesh2(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALMESH2PROC);
#define glEvalPoint1(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALPOINT1PROC);
#define glEvalPoint2(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALPOINT2PROC);
#define glEvaluateDepthValuesARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEVALUATEDEPTHVALUESARBPROC);
#define glExecuteProgramNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEXECUTEPROGRAMNVPROC);
#define glExtractComponentEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLEXTRACTCOMPONENTEXTPROC);
#define glFeedbackBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFEEDBACKBUFFERPROC);
#define glFeedbackBufferxOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFEEDBACKBUFFERXOESPROC);
#define glFenceSync(...) (0)
typedef JELLO_GRADER_PROC(PFNGLFENCESYNCPROC);
#define glFinalCombinerInputNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFINALCOMBINERINPUTNVPROC);
#define glFinish(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFINISHPROC);
#define glFinishAsyncSGIX(...) (0)
typedef JELLO_GRADER_PROC(PFNGLFINISHASYNCSGIXPROC);
#define glFinishFenceAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFINISHFENCEAPPLEPROC);
#define glFinishFenceNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFINISHFENCENVPROC);
#define glFinishObjectAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFINISHOBJECTAPPLEPROC);
#define glFinishTextureSUNX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFINISHTEXTURESUNXPROC);
#define glFlush(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHPROC);
#define glFlushMappedBufferRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHMAPPEDBUFFERRANGEPROC);
#define glFlushMappedBufferRangeAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHMAPPEDBUFFERRANGEAPPLEPROC);
#define glFlushMappedNamedBufferRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHMAPPEDNAMEDBUFFERRANGEPROC);
#define glFlushMappedNamedBufferRangeEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHMAPPEDNAMEDBUFFERRANGEEXTPROC);
#define glFlushPixelDataRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHPIXELDATARANGENVPROC);
#define glFlushRasterSGIX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLFLUSHRASTERSGIXPROC);
#define glFlushStaticDataIBM(...) ((void)0)
