{ Windows.pas -- a headless stand-in for the parts of Delphi's Windows unit
  (user32/gdi32/opengl32) that the book programs call, on Linux over
  softgl's wgl shim (include/GL/softgl_wgl.h).

  A window (HWND) is a small integer the Forms stand-in registers with its
  client size; GetDC(hwnd) gives that window's device context, an offscreen
  surface from softglCreateDC.  HDC and HWND stay small integers, as the
  book's `f_Hdc: longInt` expects (a softgl DC is a pointer, which does not
  fit in a LongInt on x86-64), so this unit keeps a table from handle to
  softgl DC and translates in each call.

  Fonts: CreateFont returns a handle that only remembers height, weight and
  charset; SelectObject(dc, font) selects it with softglSelectFont, so that
  wglUseFontBitmaps draws with softgl's built-in bitmap fonts
  (docs/fonts.md).  GetStockObject(SYSTEM_FONT) is the 16 px bold font.

  Time: GetTickCount returns a clock the driver sets (SetTickCount), so
  animated programs give the same frame on every run. }
unit Windows;

{$mode delphi}

interface

type
  BOOL = LongBool;
  DWORD = LongWord;
  UINT = LongWord;
  HWND = LongWord;
  HDC = LongWord;
  HGDIOBJ = LongWord;
  HFONT = LongWord;
  HGLRC = PtrUInt;
  PAnsiChar = System.PAnsiChar;

  TPixelFormatDescriptor = packed record
    nSize: Word;
    nVersion: Word;
    dwFlags: DWORD;
    iPixelType: Byte;
    cColorBits: Byte;
    cRedBits, cRedShift, cGreenBits, cGreenShift, cBlueBits, cBlueShift: Byte;
    cAlphaBits, cAlphaShift: Byte;
    cAccumBits, cAccumRedBits, cAccumGreenBits, cAccumBlueBits, cAccumAlphaBits: Byte;
    cDepthBits: Byte;
    cStencilBits: Byte;
    cAuxBuffers: Byte;
    iLayerType: Byte;
    bReserved: Byte;
    dwLayerMask, dwVisibleMask, dwDamageMask: DWORD;
  end;
  PIXELFORMATDESCRIPTOR = TPixelFormatDescriptor;
  PPixelFormatDescriptor = ^TPixelFormatDescriptor;

const
  PFD_DOUBLEBUFFER = $00000001;
  PFD_DRAW_TO_WINDOW = $00000004;
  PFD_SUPPORT_OPENGL = $00000020;
  PFD_TYPE_RGBA = 0;
  PFD_MAIN_PLANE = 0;

  FW_DONTCARE = 0;
  FW_NORMAL = 400;
  FW_BOLD = 700;
  ANSI_CHARSET = 0;
  DEFAULT_CHARSET = 1;
  RUSSIAN_CHARSET = 204;
  OUT_TT_PRECIS = 4;
  CLIP_DEFAULT_PRECIS = 0;
  ANTIALIASED_QUALITY = 4;
  FF_DONTCARE = 0;
  DEFAULT_PITCH = 0;
  SYSTEM_FONT = 13;

  MB_OK = 0;

type
  TRect = record Left, Top, Right, Bottom: LongInt; end;
  TPaintStruct = record
    hdc: HDC;
    fErase: BOOL;
    rcPaint: TRect;
    fRestore, fIncUpdate: BOOL;
    rgbReserved: array[0..31] of Byte;
  end;

{ user32 }
function GetDC(Wnd: HWND): HDC;
function ReleaseDC(Wnd: HWND; aDC: HDC): Integer;
function DeleteDC(aDC: HDC): BOOL;
function InvalidateRect(Wnd: HWND; lpRect: Pointer; bErase: BOOL): BOOL;
function MessageBox(Wnd: HWND; lpText, lpCaption: PAnsiChar; uType: UINT): Integer;
function GetTickCount: DWORD;
function BeginPaint(Wnd: HWND; var lpPaint: TPaintStruct): HDC;
function EndPaint(Wnd: HWND; const lpPaint: TPaintStruct): BOOL;

{ gdi32 }
function ChoosePixelFormat(DC: HDC; p2: PPixelFormatDescriptor): Integer;
function SetPixelFormat(DC: HDC; PixelFormat: Integer; FormatDef: PPixelFormatDescriptor): BOOL;
function DescribePixelFormat(DC: HDC; p2: Integer; p3: UINT; var p4: TPixelFormatDescriptor): Integer;
function SwapBuffers(DC: HDC): BOOL;
function CreateFont(nHeight, nWidth, nEscapement, nOrientaion, fnWeight: Integer;
  fdwItalic, fdwUnderline, fdwStrikeOut, fdwCharSet, fdwOutputPrecision,
  fdwClipPrecision, fdwQuality, fdwPitchAndFamily: DWORD; lpszFace: PAnsiChar): HFONT;
function GetStockObject(Index: Integer): HGDIOBJ;
function SelectObject(DC: HDC; p2: HGDIOBJ): HGDIOBJ;
function DeleteObject(p1: HGDIOBJ): BOOL;

{ opengl32 }
function wglCreateContext(DC: HDC): HGLRC;
function wglDeleteContext(p1: HGLRC): BOOL;
function wglMakeCurrent(DC: HDC; p2: HGLRC): BOOL;
function wglGetCurrentContext: HGLRC;
function wglUseFontBitmaps(DC: HDC; p2, p3, p4: DWORD): BOOL;

{ Not Windows: what the Forms stand-in and the drivers use. }
function RegisterWindow(ClientWidth, ClientHeight: Integer): HWND;
function WindowDC(Wnd: HWND): HDC;          { the window's DC, creating it }
function SoftglDC(DC: HDC): Pointer;         { the softgl DC behind a handle }
procedure SetTickCount(t: DWORD);
var
  MessageBoxCount: Integer;                  { MessageBox calls so far }

implementation

{ softgl's exports (softgl_wgl.h).  stdcall = the platform C convention on
  x86-64 Linux, as APIENTRY is there. }
function softglCreateDC(width, height: LongInt): Pointer; stdcall; external 'GL';
function softglDestroyDC(dc: Pointer): LongInt; stdcall; external 'GL';
function softglSelectFont(dc: Pointer; height, weight, charset: LongInt): LongInt; stdcall; external 'GL';
function sgChoosePixelFormat(dc: Pointer; pfd: PPixelFormatDescriptor): LongInt; stdcall; external 'GL' name 'wglChoosePixelFormat';
function sgSetPixelFormat(dc: Pointer; fmt: LongInt; pfd: PPixelFormatDescriptor): LongInt; stdcall; external 'GL' name 'wglSetPixelFormat';
function sgDescribePixelFormat(dc: Pointer; fmt: LongInt; n: LongWord; pfd: PPixelFormatDescriptor): LongInt; stdcall; external 'GL' name 'wglDescribePixelFormat';
function sgSwapBuffers(dc: Pointer): LongInt; stdcall; external 'GL' name 'wglSwapBuffers';
function sgCreateContext(dc: Pointer): Pointer; stdcall; external 'GL' name 'wglCreateContext';
function sgDeleteContext(rc: Pointer): LongInt; stdcall; external 'GL' name 'wglDeleteContext';
function sgMakeCurrent(dc: Pointer; rc: Pointer): LongInt; stdcall; external 'GL' name 'wglMakeCurrent';
function sgGetCurrentContext: Pointer; stdcall; external 'GL' name 'wglGetCurrentContext';
function sgUseFontBitmapsA(dc: Pointer; first, count, base: LongWord): LongInt; stdcall; external 'GL' name 'wglUseFontBitmapsA';

type
  TWindowRec = record
    W, H: Integer;
    DC: HDC;
  end;
  TFontRec = record
    Height, Weight, Charset: Integer;
  end;

var
  Windows_: array of TWindowRec;      { HWND n is Windows_[n-1] }
  DCs: array of Pointer;              { HDC n is DCs[n-1] }
  Fonts: array of TFontRec;           { HFONT $1000+n is Fonts[n] }
  Tick: DWORD;

const
  FontBase = $1000;

function RegisterWindow(ClientWidth, ClientHeight: Integer): HWND;
begin
  SetLength(Windows_, Length(Windows_) + 1);
  Windows_[High(Windows_)].W := ClientWidth;
  Windows_[High(Windows_)].H := ClientHeight;
  Windows_[High(Windows_)].DC := 0;
  Result := Length(Windows_);
end;

function SoftglDC(DC: HDC): Pointer;
begin
  if (DC >= 1) and (DC <= LongWord(Length(DCs))) then Result := DCs[DC - 1]
  else Result := nil;
end;

function WindowDC(Wnd: HWND): HDC;
var p: Pointer;
begin
  Result := 0;
  if (Wnd < 1) or (Wnd > LongWord(Length(Windows_))) then Exit;
  with Windows_[Wnd - 1] do
  begin
    if DC = 0 then
    begin
      p := softglCreateDC(W, H);
      if p = nil then Exit;
      SetLength(DCs, Length(DCs) + 1);
      DCs[High(DCs)] := p;
      DC := Length(DCs);
    end;
    Result := DC;
  end;
end;

function GetDC(Wnd: HWND): HDC;
begin
  Result := WindowDC(Wnd);
end;

function ReleaseDC(Wnd: HWND; aDC: HDC): Integer;
begin
  { A window's DC lives as long as the window (CS_OWNDC), as OpenGL
    windows on Windows have it; nothing to free here. }
  Result := Ord(SoftglDC(aDC) <> nil);
end;

function DeleteDC(aDC: HDC): BOOL;
begin
  { Ex72 calls DeleteDC on a GetDC handle: an error in GDI, harmless. }
  Result := False;
end;

function InvalidateRect(Wnd: HWND; lpRect: Pointer; bErase: BOOL): BOOL;
begin
  Result := True;   { the driver decides when to paint }
end;

function MessageBox(Wnd: HWND; lpText, lpCaption: PAnsiChar; uType: UINT): Integer;
begin
  Inc(MessageBoxCount);
  WriteLn('MessageBox [', lpCaption, ']: ', lpText);
  Result := 1;
end;

function BeginPaint(Wnd: HWND; var lpPaint: TPaintStruct): HDC;
begin
  FillChar(lpPaint, SizeOf(lpPaint), 0);
  lpPaint.hdc := WindowDC(Wnd);
  Result := lpPaint.hdc;
end;

function EndPaint(Wnd: HWND; const lpPaint: TPaintStruct): BOOL;
begin
  Result := True;
end;

function GetTickCount: DWORD;
begin
  Result := Tick;
end;

procedure SetTickCount(t: DWORD);
begin
  Tick := t;
end;

function ChoosePixelFormat(DC: HDC; p2: PPixelFormatDescriptor): Integer;
begin
  Result := sgChoosePixelFormat(SoftglDC(DC), p2);
end;

function SetPixelFormat(DC: HDC; PixelFormat: Integer; FormatDef: PPixelFormatDescriptor): BOOL;
begin
  Result := sgSetPixelFormat(SoftglDC(DC), PixelFormat, FormatDef) <> 0;
end;

function DescribePixelFormat(DC: HDC; p2: Integer; p3: UINT; var p4: TPixelFormatDescriptor): Integer;
begin
  Result := sgDescribePixelFormat(SoftglDC(DC), p2, p3, @p4);
end;

function SwapBuffers(DC: HDC): BOOL;
begin
  Result := sgSwapBuffers(SoftglDC(DC)) <> 0;
end;

function CreateFont(nHeight, nWidth, nEscapement, nOrientaion, fnWeight: Integer;
  fdwItalic, fdwUnderline, fdwStrikeOut, fdwCharSet, fdwOutputPrecision,
  fdwClipPrecision, fdwQuality, fdwPitchAndFamily: DWORD; lpszFace: PAnsiChar): HFONT;
begin
  { The face name is not used: softgl has one family of bitmap fonts. }
  SetLength(Fonts, Length(Fonts) + 1);
  Fonts[High(Fonts)].Height := nHeight;
  Fonts[High(Fonts)].Weight := fnWeight;
  Fonts[High(Fonts)].Charset := fdwCharSet;
  Result := FontBase + High(Fonts);
end;

function GetStockObject(Index: Integer): HGDIOBJ;
begin
  if Index = SYSTEM_FONT then
    Result := CreateFont(16, 0, 0, 0, FW_BOLD, 0, 0, 0, DEFAULT_CHARSET, 0, 0, 0, 0, 'System')
  else
    Result := 0;
end;

function SelectObject(DC: HDC; p2: HGDIOBJ): HGDIOBJ;
var i: Integer;
begin
  Result := 0;
  i := Integer(p2) - FontBase;
  if (i < 0) or (i > High(Fonts)) or (SoftglDC(DC) = nil) then Exit;
  if softglSelectFont(SoftglDC(DC), Fonts[i].Height, Fonts[i].Weight, Fonts[i].Charset) <> 0 then
    Result := p2;
end;

function DeleteObject(p1: HGDIOBJ): BOOL;
begin
  Result := True;   { the lists own their glyph bitmaps already }
end;

function wglCreateContext(DC: HDC): HGLRC;
begin
  Result := HGLRC(sgCreateContext(SoftglDC(DC)));
end;

function wglDeleteContext(p1: HGLRC): BOOL;
begin
  Result := sgDeleteContext(Pointer(p1)) <> 0;
end;

function wglMakeCurrent(DC: HDC; p2: HGLRC): BOOL;
begin
  Result := sgMakeCurrent(SoftglDC(DC), Pointer(p2)) <> 0;
end;

function wglGetCurrentContext: HGLRC;
begin
  Result := HGLRC(sgGetCurrentContext);
end;

function wglUseFontBitmaps(DC: HDC; p2, p3, p4: DWORD): BOOL;
begin
  Result := sgUseFontBitmapsA(SoftglDC(DC), p2, p3, p4) <> 0;
end;

end.
